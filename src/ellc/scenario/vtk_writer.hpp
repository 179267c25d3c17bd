#pragma once
// ParaView output: legacy VTK files (ASCII POLYDATA), two per frame. In the particles' file each
// particle is a vertex with the symmetric tensor R diag(a, b, c) Rᵀ: in ParaView, Tensor Glyph
// with a sphere source, "Extract Eigenvalues" on and scale factor 2 draws each ellipsoid with its
// true semi-axes. The contacts' file has a line per contact.

#include <string>

#include "ellc/engine/simulation.hpp"

namespace ellc::scenario {

void write_vtk_frame(const std::string& path, const engine::Simulation& simulation);

// The contacts of the same frame (Simulation::for_each_contact), a second POLYDATA file: one line
// cell per contact, between the two centres (a pair; j's periodic image, so a line may leave the
// box) or from the centre to the contact point (a wall). Cell data: normal_force (µN), overlap δ
// and max_overlap δ_* (µm), regime (0 separated, i.e. overlapping below δ_p; 1 elastic,
// 2 elastic_plastic, 3 fully_plastic, 4 unloading), size_ratio c_c/r̂ (ValidityReport's),
// wall (−1 a pair, 0 the floor, 1 the plate) and the force vector (on j, or on the wall).
void write_vtk_contacts(const std::string& path, const engine::Simulation& simulation);

}  // namespace ellc::scenario
