#include "ellc/engine/pair_geometry.hpp"

namespace ellc::engine {

// Placeholder until the general narrow phase of src/ellc/geometry lands.
PairSolution solve_ellipsoid_pair(const BodyRef&, const BodyRef&, ContactHistory&, const NormalContext&) noexcept {
  PairSolution solution;
  solution.status = PairStatus::failed;
  return solution;
}

PairSolution solve_ellipsoid_wall(const BodyRef&, const Wall&, ContactHistory&, const NormalContext&) noexcept {
  PairSolution solution;
  solution.status = PairStatus::failed;
  return solution;
}

}  // namespace ellc::engine

#include "ellc/engine/packing.hpp"
namespace ellc::engine {
OverlapTest ellipsoid_overlap_test(double) { return {}; }
}  // namespace ellc::engine
