// The ellipsoid paths of solve_pair / solve_wall: the geometry layer's narrow phase (common
// normal, warm-started from the pair's previous normal) and wall contact, then normal_contact()
// for the constants and the law. Nothing here re-derives a formula of the law.

#include <algorithm>

#include "ellc/contact/normal_contact.hpp"
#include "ellc/contact/pair_contact.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/geometry/wall_contact.hpp"

namespace ellc {

namespace {

// Calls `use` with the posed ellipsoid of the body: the prebuilt one when it sits where the body
// is, a copy of it moved to the image's centre for a periodic image, else one built here.
template <typename Use>
auto with_shape(const BodyRef& body, Use&& use) noexcept {
  if (body.shape != nullptr) {
    if (body.shape->center() == body.centre) return use(*body.shape);
    return use(body.shape->moved_to(body.centre));
  }
  return use(Ellipsoid(body.semi_axes, Pose{body.centre, body.orientation}));
}

PairSolution with_law(const NarrowPhaseResult& found, double mean_radius_sum, ContactHistory& history,
                      ContactCache& cache, const InteractionContext& context) noexcept {
  PairSolution solution;
  solution.iterations = found.iterations;
  if (found.status == NarrowPhaseStatus::failed) {
    solution.status = PairStatus::failed;
    return solution;
  }
  if (found.status == NarrowPhaseStatus::separated || !(found.geometry.overlap > 0.0)) {
    // g(n) ≤ 0 along the stored normal: the clearance the next steps' shortcut would test.
    if (found.status == NarrowPhaseStatus::separated) solution.clearance = std::max(-found.geometry.overlap, 0.0);
    return solution;
  }
  // Only the constants the law reads: the cache keeps them for the energies of yielded contacts and
  // c_c/r̂, which read no more (ConstantsScope).
  const NormalContact contact = normal_contact(found.geometry, context.material, mean_radius_sum, context.model.hertz,
                                               context.model.law, history.max_overlap, ConstantsScope::law_reads);
  cache.constants = contact.constants;
  solution.status = PairStatus::contact;
  solution.normal = found.geometry.normal;
  solution.point = contact.application_point;
  solution.overlap = found.geometry.overlap;
  solution.law = contact.law;
  solution.branch = contact.branch;
  solution.constants = &cache.constants;
  history.max_overlap = solution.law.max_overlap;
  cache.last_overlap = solution.overlap;
  return solution;
}

}  // namespace

PairSolution solve_ellipsoid_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history,
                                  ContactCache& cache, const InteractionContext& context) noexcept {
  // Apart last step, and last step's separating axis still separates: no narrow phase. Most
  // candidate pairs of a dense packing are such near misses. (Images of J share its shape S_J.)
  // A sphere meeting an ellipsoid (shape null) re-solves and re-stores its warm start every step
  // instead; it reports no clearance either, since skipping it would skip that update.
  const bool shortcut = body_i.shape != nullptr && body_j.shape != nullptr;
  if (shortcut && !history.active() && history.warm_valid != 0.0) {
    const auto& axis = history.warm_normal;
    const double overlap = overlap_along(*body_i.shape, *body_j.shape, body_j.centre - body_i.centre,
                                         Eigen::Vector3d(axis[0], axis[1], axis[2]));
    if (overlap < 0.0) {
      PairSolution apart;
      apart.clearance = -overlap;
      return apart;
    }
  }
  const NarrowPhaseWarmStart warm = history.warm_start();
  const NarrowPhaseResult found = with_shape(body_i, [&](const Ellipsoid& ellipsoid_i) {
    return with_shape(body_j, [&](const Ellipsoid& ellipsoid_j) {
      return ellipsoid_contact(ellipsoid_i, ellipsoid_j, warm.valid ? &warm : nullptr, context.narrow_phase);
    });
  });
  if (found.status != NarrowPhaseStatus::failed) history.set_warm_start(found.warm_start);
  PairSolution solution = with_law(found, body_i.mean_radius + body_j.mean_radius, history, cache, context);
  if (!shortcut) solution.clearance = 0.0;
  return solution;
}

PairSolution solve_ellipsoid_wall(const BodyRef& body, const WallPlane& wall, ContactHistory& history,
                                  ContactCache& cache, const InteractionContext& context) noexcept {
  const Plane plane{Eigen::Vector3d(0.0, 0.0, wall.position), Eigen::Vector3d(0.0, 0.0, wall.side)};
  return with_shape(body, [&](const Ellipsoid& ellipsoid) {
    return with_law(wall_contact(ellipsoid, plane), wall_mean_radius_sum(ellipsoid), history, cache, context);
  });
}

}  // namespace ellc
