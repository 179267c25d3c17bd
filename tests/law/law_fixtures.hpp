#pragma once
// Contact constants of the paper's validation geometries, built through the public path.
#include <Eigen/Core>

#include "ellc/geometry/tip_contact.hpp"
#include "ellc/law/contact_law.hpp"
#include "support/nmc.hpp"

namespace ellc::testing {

using ellc::test::kNmc;

inline Eigen::Vector3d from_aspect(double b, double c, double mean) {
  const Eigen::Vector3d ratios(1.0, b, c);
  return ratios * (mean / std::cbrt(ratios.prod()));
}

inline ContactConstants tip_constants(const Eigen::Vector3d& axes_i, const Eigen::Vector3d& axes_j,
                                      double twist_i = 0.0, double twist_j = 0.0,
                                      HertzMode mode = HertzMode::hale, const LawParameters& law = {}) {
  const TipContact tip = tip_contact({axes_i, twist_i}, {axes_j, twist_j});
  return make_contact_constants(mix(kNmc, kNmc), tip.body_i, tip.body_j, tip.alpha,
                                mean_radius(axes_i) + mean_radius(axes_j), mode, law);
}

inline ContactConstants paper_case1(HertzMode mode = HertzMode::hale) {
  return tip_constants(from_aspect(1.25, 1.5, 4.675), from_aspect(0.5, 0.8, 4.675), 0.0, 0.0, mode);
}
inline ContactConstants paper_case2(HertzMode mode = HertzMode::hale) {
  return tip_constants(from_aspect(1.0, 0.8, 10.0), from_aspect(1.25, 1.25, 10.0), 0.0, 0.0, mode);
}

}  // namespace ellc::testing
