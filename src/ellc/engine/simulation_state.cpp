// Simulation::write_state / read_state: the checkpoint body. Everything the next step reads is
// stored, including the neighbour list and its reference positions, so that a restarted run
// rebuilds the list at the same steps and reproduces the uninterrupted run bit for bit.

#include <istream>
#include <ostream>

#include "ellc/engine/binary_io.hpp"
#include "ellc/engine/simulation.hpp"

namespace ellc::engine {

// Found by argument-dependent lookup from the templates of binary_io.hpp.
void put(std::ostream& out, const ContactHistory& h) {
  using binary::put;
  put(out, h.max_overlap);
  put(out, h.tangential_spring);
  put(out, h.last_overlap);
  put(out, h.active);
  put(out, h.constants_cached);
  put(out, h.constants);
  put(out, h.warm_start);
}
void get(std::istream& in, ContactHistory& h) {
  using binary::get;
  get(in, h.max_overlap);
  get(in, h.tangential_spring);
  get(in, h.last_overlap);
  get(in, h.active);
  get(in, h.constants_cached);
  get(in, h.constants);
  get(in, h.warm_start);
}
void put(std::ostream& out, const PairSlot& pair) {
  using binary::put;
  put(out, pair.key);
  put(out, pair.i);
  put(out, pair.j);
  put(out, pair.shift);
  put(out, pair.history);
}
void get(std::istream& in, PairSlot& pair) {
  using binary::get;
  get(in, pair.key);
  get(in, pair.i);
  get(in, pair.j);
  get(in, pair.shift);
  get(in, pair.history);
}

namespace {
constexpr std::uint64_t kStateTag = 0x454c4c43'44454d31ULL;  // "ELLCDEM1"
}

void Simulation::write_state(std::ostream& out) const {
  using binary::put;
  put(out, kStateTag);
  put(out, step_);
  put(out, time_);
  put(out, rebuilds_);
  put(out, released_work_);
  put(out, failures_);
  put(out, skin_);
  put(out, settings_.dt);
  put(out, settings_.gravity);
  put(out, settings_.drag_rate);
  for (const auto& wall : walls_) {
    put(out, wall.position);
    put(out, wall.velocity);
    put(out, wall.side);
    put(out, wall.force);
  }
  const auto& p = particles_;
  put(out, p.id);
  put(out, p.semi_axes);
  put(out, p.mass);
  put(out, p.inertia);
  put(out, p.mean_radius);
  put(out, p.bounding_radius);
  put(out, p.position);
  put(out, p.orientation);
  put(out, p.velocity);
  put(out, p.angular_velocity);
  put(out, p.force);
  put(out, p.torque);
  put(out, reference_position_);
  put(out, pairs_);
  for (const auto& histories : wall_history_) put(out, histories);
  // Per-contact results of the last force evaluation (regimes for the outputs).
  put(out, static_cast<std::uint64_t>(pair_results_.size()));
  for (const auto& result : pair_results_) {
    put(out, result.force_on_j);
    put(out, result.torque_i);
    put(out, result.torque_j);
    put(out, result.released_work);
    put(out, result.regime);
    put(out, result.contact);
    put(out, result.failed);
  }
  for (const auto& results : wall_results_)
    for (const auto& result : results) {
      put(out, result.force_on_wall);
      put(out, result.released_work);
      put(out, result.regime);
      put(out, result.contact);
      put(out, result.failed);
    }
}

void Simulation::read_state(std::istream& in) {
  using binary::get;
  std::uint64_t tag = 0;
  get(in, tag);
  if (tag != kStateTag) throw std::runtime_error("not an ellc dem checkpoint (bad state tag)");
  get(in, step_);
  get(in, time_);
  get(in, rebuilds_);
  get(in, released_work_);
  get(in, failures_);
  get(in, skin_);
  get(in, settings_.dt);
  get(in, settings_.gravity);
  get(in, settings_.drag_rate);
  for (auto& wall : walls_) {
    get(in, wall.position);
    get(in, wall.velocity);
    get(in, wall.side);
    get(in, wall.force);
  }
  auto& p = particles_;
  get(in, p.id);
  get(in, p.semi_axes);
  get(in, p.mass);
  get(in, p.inertia);
  get(in, p.mean_radius);
  get(in, p.bounding_radius);
  get(in, p.position);
  get(in, p.orientation);
  get(in, p.velocity);
  get(in, p.angular_velocity);
  get(in, p.force);
  get(in, p.torque);
  get(in, reference_position_);
  get(in, pairs_);
  for (auto& histories : wall_history_) get(in, histories);
  std::uint64_t pair_count = 0;
  get(in, pair_count);
  if (pair_count != pairs_.size()) throw std::runtime_error("checkpoint is corrupt (pair results)");
  pair_results_.assign(pairs_.size(), PairResult{});
  for (auto& result : pair_results_) {
    get(in, result.force_on_j);
    get(in, result.torque_i);
    get(in, result.torque_j);
    get(in, result.released_work);
    get(in, result.regime);
    get(in, result.contact);
    get(in, result.failed);
  }
  const std::size_t count = p.size();
  for (auto& results : wall_results_) {
    results.assign(count, WallResult{});
    for (auto& result : results) {
      get(in, result.force_on_wall);
      get(in, result.released_work);
      get(in, result.regime);
      get(in, result.contact);
      get(in, result.failed);
    }
  }
  is_sphere_.resize(count);
  for (std::size_t slot = 0; slot < count; ++slot) {
    const auto& axes = p.semi_axes[slot];
    is_sphere_[slot] = axes.x() == axes.y() && axes.x() == axes.z();
  }
  omega_world_.assign(count, Eigen::Vector3d::Zero());
  shapes_.assign(count, Ellipsoid(Eigen::Vector3d::Ones()));
}

}  // namespace ellc::engine
