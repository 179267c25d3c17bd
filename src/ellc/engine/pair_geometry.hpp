#pragma once
// The engine's view of the narrow phase: for a pair (or a particle and a wall) the contact
// normal, the point where the forces act, the overlap, the law's result and the constants.
// Spheres take an exact closed-form path with their contact constants cached per contact;
// ellipsoids go through the geometry layer (ellipsoid_contact / wall_contact + normal_contact).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ellc/engine/contact_history.hpp"
#include "ellc/engine/settings.hpp"
#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/law/contact_law.hpp"

namespace ellc::engine {

enum class PairStatus { contact, separated, failed };

struct PairSolution {
  PairStatus status = PairStatus::separated;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, I → J (particle → wall for walls)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // where the contact forces act
  double overlap = 0.0;
  // Separated: a clearance the bodies are proven apart by along one fixed axis (they stay apart
  // while their points move less than this in total), given only where re-testing the pair in
  // that time would change nothing (the engine then skips it); 0 otherwise.
  double clearance = 0.0;
  LawResult law;
  const ContactConstants* constants = nullptr;  // points into the history (valid while it lives)
};

// Material data every contact evaluation needs, built once from the settings.
struct NormalContext {
  ContactMaterial material;  // E_e and Y (Y unreachable for NormalModel::hertz)
  HertzMode hertz = HertzMode::hale;
  LawParameters law;
  NarrowPhaseOptions narrow_phase;
};

[[nodiscard]] NormalContext make_normal_context(const ContactSettings& settings) noexcept;

// A posed body as the adapter sees it.
struct BodyRef {
  const Eigen::Vector3d& semi_axes;
  Eigen::Vector3d centre;  // image position for periodic neighbours
  const Eigen::Quaterniond& orientation;
  double mean_radius;
  const Ellipsoid* shape = nullptr;  // prebuilt for this step (ellipsoids; null → built on demand)
};

// Two bodies; `spheres` selects the closed-form path. Updates the history's constants and
// warm start, never its δ_* (the caller stores law.max_overlap).
[[nodiscard]] PairSolution solve_pair(const BodyRef& body_i, const BodyRef& body_j, bool spheres,
                                      ContactHistory& history, const NormalContext& context) noexcept;

// A body against a wall, mirror-image convention: r̂^{I,J} = 2 r̂^I, the wall flat (κ = 0).
[[nodiscard]] PairSolution solve_wall(const BodyRef& body, const Wall& wall, bool sphere, ContactHistory& history,
                                      const NormalContext& context) noexcept;

// The ellipsoid paths (ellipsoid_pair.cpp), called by the two functions above.
[[nodiscard]] PairSolution solve_ellipsoid_pair(const BodyRef& body_i, const BodyRef& body_j, ContactHistory& history,
                                                const NormalContext& context) noexcept;
[[nodiscard]] PairSolution solve_ellipsoid_wall(const BodyRef& body, const Wall& wall, ContactHistory& history,
                                                const NormalContext& context) noexcept;

}  // namespace ellc::engine
