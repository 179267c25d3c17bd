#pragma once
// What one contact remembers between steps: the record both engines store unchanged, the
// built-in engine in its pair map (src/ellc/engine/broad_phase.hpp) and pair_style ellipsoid/bk in
// its history fix (integrations/lammps/fix_contact_history.hpp).
//
// Layout: nine doubles, in this order, with nothing else (checked below):
//   [0]    δ_*   largest overlap so far, the law's only history (docs/model.md §4)
//   [1..3] ξ     tangential spring, world frame, displacement of J relative to I
//   [4..6] n₀    narrow-phase warm start: the last common normal (I → J), or a separating axis
//   [7]    1 when [4..6] holds a normal, else 0
//   [8]    k_t   the spring's stiffness at the last step (the spring is rescaled when it changes)
// A contact is active while δ_* > 0: its history starts when the bodies first overlap (δ > 0) and
// is deleted when they separate (docs/model.md §5). The warm start outlives the contact: it is
// geometry, and the separating axis it then holds lets the next test skip the full narrow phase.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "ellc/geometry/narrow_phase.hpp"
#include "ellc/law/contact_constants.hpp"

namespace ellc {

struct ContactHistory {
  double max_overlap = 0.0;                   // δ_*
  std::array<double, 3> tangential_spring{};  // ξ
  std::array<double, 3> warm_normal{};        // n₀
  double warm_valid = 0.0;                    // 1: n₀ is set
  double spring_stiffness = 0.0;              // k_t of the last step

  static constexpr std::size_t kDoubles = 9;

  [[nodiscard]] bool active() const noexcept { return max_overlap > 0.0; }
  [[nodiscard]] Eigen::Map<Eigen::Vector3d> spring() noexcept {
    return Eigen::Map<Eigen::Vector3d>(tangential_spring.data());
  }
  [[nodiscard]] Eigen::Map<const Eigen::Vector3d> spring() const noexcept {
    return Eigen::Map<const Eigen::Vector3d>(tangential_spring.data());
  }
  // Elastic energy of the tangential spring, ½ k_t |ξ|².
  [[nodiscard]] double spring_energy() const noexcept { return 0.5 * spring_stiffness * spring().squaredNorm(); }
  [[nodiscard]] NarrowPhaseWarmStart warm_start() const noexcept { return {warm_normal, warm_valid != 0.0}; }
  void set_warm_start(const NarrowPhaseWarmStart& warm) noexcept {
    warm_normal = warm.normal;
    warm_valid = warm.valid ? 1.0 : 0.0;
  }
  // Ends the contact (the bodies separated): δ_* and ξ are deleted, the warm start is kept.
  void end_contact() noexcept {
    max_overlap = 0.0;
    tangential_spring = {};
    spring_stiffness = 0.0;
  }

  // The flat form, for stores that keep raw doubles (LAMMPS's per-atom arrays, restart files).
  void write_to(double* values) const noexcept {
    std::memcpy(values, static_cast<const void*>(this), sizeof(ContactHistory));
  }
  [[nodiscard]] static ContactHistory read_from(const double* values) noexcept {
    ContactHistory history;
    std::memcpy(static_cast<void*>(&history), values, sizeof(ContactHistory));
    return history;
  }
};
static_assert(std::is_trivially_copyable_v<ContactHistory> && std::is_standard_layout_v<ContactHistory>);
static_assert(sizeof(ContactHistory) == ContactHistory::kDoubles * sizeof(double), "the layout above, no padding");

// Derived per-contact data a caller may keep beside the history to save work; never needed for
// the physics of the next step. Sphere pairs build their constants once per contact (they cannot
// change); `constants` is otherwise the last configuration's, which the energy observables use.
struct ContactCache {
  ContactConstants constants;
  double last_overlap = 0.0;  // δ at the last evaluation (stored elastic energy)
  bool constants_cached = false;
};

}  // namespace ellc
