#pragma once
// ParaView output: one legacy VTK file (ASCII POLYDATA) per frame. Each particle is a vertex
// with the symmetric tensor R diag(a, b, c) Rᵀ: in ParaView, Tensor Glyph with a sphere source,
// "Extract Eigenvalues" on and scale factor 2 draws each ellipsoid with its true semi-axes.

#include <string>

#include "ellc/engine/simulation.hpp"

namespace ellc::scenario {

void write_vtk_frame(const std::string& path, const engine::Simulation& simulation);

}  // namespace ellc::scenario
