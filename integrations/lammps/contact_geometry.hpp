#pragma once
// Adapter between the pair style and the project's geometry layer: everything the force model
// needs about where and how two ellipsoids touch.

#include <Eigen/Core>

#include "contact_model.hpp"
#include "ellc/hertz/elliptic_hertz.hpp"

namespace ellc_lammps {

struct PairGeometry {
  bool valid = true;        // false: the narrow phase failed (reported by the pair style)
  double overlap = 0.0;     // δ > 0 when touching
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // a → b
  ellc::PrincipalCurvatures curvature_a;
  ellc::PrincipalCurvatures curvature_b;
  double alpha = 0.0;
};

// Number of doubles of narrow-phase warm start kept in the contact history.
[[nodiscard]] int warm_start_size();

// `warm_start`: warm_start_size() doubles, all zero for a new contact; updated in place.
[[nodiscard]] PairGeometry pair_geometry(const BodyState& a, const BodyState& b, double* warm_start);

}  // namespace ellc_lammps
