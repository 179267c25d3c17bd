#include "ellc/engine/pair_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace ellc::engine {

NormalContext make_normal_context(const ContactSettings& settings) noexcept {
  NormalContext context;
  context.material = mix(settings.material, settings.material);
  // Plain Hertz is the same law with a yield stress it never reaches (δ_Y ≫ any overlap).
  if (settings.normal_model == NormalModel::hertz) context.material.yield_stress = 1e30;
  context.hertz = settings.hertz;
  context.law = settings.law;
  context.narrow_phase.final_step = settings.narrow_phase_final_step;
  context.narrow_phase.surface_curvatures = false;  // the law needs A and B only
  return context;
}

namespace {

const ContactConstants& cached_constants(ContactHistory& history, PrincipalCurvatures body_i,
                                         PrincipalCurvatures body_j, double mean_radius_sum,
                                         const NormalContext& context) noexcept {
  if (!history.constants_cached) {
    history.constants =
        make_contact_constants(context.material, body_i, body_j, 0.0, mean_radius_sum, context.hertz, context.law);
    history.constants_cached = true;
  }
  return history.constants;
}

PairSolution sphere_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history,
                         const NormalContext& context) noexcept {
  PairSolution solution;
  const double radius_i = body_i.semi_axes.x();
  const double radius_j = body_j.semi_axes.x();
  const Eigen::Vector3d joint = body_j.centre - body_i.centre;
  const double distance = joint.norm();
  const double overlap = radius_i + radius_j - distance;
  if (!(overlap > 0.0)) {
    solution.clearance = std::max(-overlap, 0.0);
    return solution;
  }
  if (!(distance > 0.0)) {
    solution.status = PairStatus::failed;  // coincident centres: no normal
    return solution;
  }
  solution.status = PairStatus::contact;
  solution.normal = joint / distance;
  solution.overlap = overlap;
  solution.point = body_i.centre + (radius_i - 0.5 * overlap) * solution.normal;
  const ContactConstants& constants =
      cached_constants(history, {1.0 / radius_i, 1.0 / radius_i}, {1.0 / radius_j, 1.0 / radius_j},
                       body_i.mean_radius + body_j.mean_radius, context);
  solution.law = evaluate_contact(constants, overlap, history.max_overlap);
  solution.constants = &constants;
  return solution;
}

PairSolution sphere_wall(const BodyRef& body, const Wall& wall, ContactHistory& history,
                         const NormalContext& context) noexcept {
  PairSolution solution;
  const double radius = body.semi_axes.x();
  const double gap = wall.side * (body.centre.z() - wall.position);  // centre height above the wall
  const double overlap = radius - gap;
  if (!(overlap > 0.0)) return solution;
  solution.status = PairStatus::contact;
  solution.normal = Eigen::Vector3d(0.0, 0.0, -wall.side);
  solution.overlap = overlap;
  solution.point = Eigen::Vector3d(body.centre.x(), body.centre.y(), wall.position);
  const ContactConstants& constants =
      cached_constants(history, {1.0 / radius, 1.0 / radius}, {0.0, 0.0}, 2.0 * body.mean_radius, context);
  solution.law = evaluate_contact(constants, overlap, history.max_overlap);
  solution.constants = &constants;
  return solution;
}

}  // namespace

PairSolution solve_pair(const BodyRef& body_i, const BodyRef& body_j, bool spheres, ContactHistory& history,
                        const NormalContext& context) noexcept {
  if (spheres) return sphere_pair(body_i, body_j, history, context);
  return solve_ellipsoid_pair(body_i, body_j, history, context);
}

PairSolution solve_wall(const BodyRef& body, const Wall& wall, bool sphere, ContactHistory& history,
                        const NormalContext& context) noexcept {
  if (sphere) return sphere_wall(body, wall, history, context);
  return solve_ellipsoid_wall(body, wall, history, context);
}

}  // namespace ellc::engine
