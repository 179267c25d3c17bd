// Simulation::write_state / read_state: the checkpoint body. Everything the next step reads is
// stored, including the neighbour list and its reference positions, so that a restarted run
// rebuilds the list at the same steps and reproduces the uninterrupted run bit for bit.
// One field list (state_fields) serves both directions, so writer and reader cannot drift apart.

#include <istream>
#include <ostream>
#include <type_traits>

#include "ellc/engine/binary_io.hpp"
#include "ellc/engine/simulation.hpp"

namespace ellc::engine {

namespace {

struct Writer {
  std::ostream& out;
  template <typename T>
  void operator()(const T& value) {
    binary::put(out, value);
  }
};

struct Reader {
  std::istream& in;
  template <typename T>
  void operator()(T& value) {
    binary::get(in, value);
  }
};

// The shared history record as its eight doubles (contact_history.hpp), then the engine's cache.
template <typename Io, typename History, typename Cache>
void history_fields(Io&& io, History& h, Cache& c) {
  io(h.max_overlap);
  io(h.tangential_spring);
  io(h.warm_normal);
  io(h.warm_valid);
  io(h.spring_stiffness);
  io(c.last_overlap);
  io(c.constants_cached);
  io(c.constants);
}

template <typename Io, typename Pair>
void pair_fields(Io&& io, Pair& pair) {
  io(pair.key);
  io(pair.i);
  io(pair.j);
  io(pair.shift);
  history_fields(io, pair.history, pair.cache);
}

constexpr std::uint64_t kStateTag = 0x454c4c43'44454d32ULL;  // "ELLCDEM2": the shared history record (was 1)

}  // namespace

// Found by argument-dependent lookup from the vector templates of binary_io.hpp.
void put(std::ostream& out, const WallContact& wall) { history_fields(Writer{out}, wall.history, wall.cache); }
void get(std::istream& in, WallContact& wall) { history_fields(Reader{in}, wall.history, wall.cache); }
void put(std::ostream& out, const PairSlot& pair) { pair_fields(Writer{out}, pair); }
void get(std::istream& in, PairSlot& pair) { pair_fields(Reader{in}, pair); }

template <typename Io, typename Self>
void Simulation::state_fields(Io& io, Self& self) {
  io(self.step_);
  io(self.time_);
  io(self.rebuilds_);
  io(self.released_work_);
  io(self.damping_dissipation_);
  io(self.friction_dissipation_);
  io(self.failures_);
  io(self.skin_);
  io(self.settings_.dt);
  io(self.settings_.gravity);
  io(self.settings_.drag_rate);
  for (auto& wall : self.walls_) {
    io(wall.position);
    io(wall.velocity);
    io(wall.side);
    io(wall.force);
    io(wall.work);
  }
  auto& p = self.particles_;
  io(p.id);
  io(p.semi_axes);
  io(p.mass);
  io(p.inertia);
  io(p.mean_radius);
  io(p.bounding_radius);
  io(p.position);
  io(p.orientation);
  io(p.velocity);
  io(p.angular_velocity);
  io(p.force);
  io(p.torque);
  io(self.reference_position_);
  io(self.pairs_);
  for (auto& histories : self.wall_history_) io(histories);
  // Results of the last force evaluation (the regimes the outputs report).
  const auto tally = [&io](auto& result) {
    io(result.released_work);
    io(result.damping_dissipation);
    io(result.friction_dissipation);
    io(result.regime);
    io(result.contact);
    io(result.failed);
  };
  const auto pair_result = [&io, &tally](auto& result) {
    io(result.force_on_j);
    io(result.torque_i);
    io(result.torque_j);
    tally(result);
  };
  const auto wall_result = [&io, &tally](auto& result) {
    io(result.force_on_wall);
    tally(result);
  };
  // Slots not written this step are stored as empty results; reading marks the slots that hold
  // something as written (holds_something), which is what the step that wrote them had set.
  const auto results = [](auto& stored, auto& reported, auto&& one) {
    using Result = std::decay_t<decltype(stored[0])>;
    for (std::size_t k = 0; k < stored.size(); ++k) {
      if constexpr (std::is_same_v<Io, Reader>) {
        one(stored[k]);
        reported[k] = holds_something(stored[k]) ? 1 : 0;
      } else {
        Result copy = reported[k] != 0 ? stored[k] : Result{};
        one(copy);
      }
    }
  };
  if constexpr (std::is_same_v<Io, Reader>) {
    self.pair_results_.assign(self.pairs_.size(), PairResult{});
    self.pair_reported_.assign(self.pairs_.size(), 0);
    for (int w = 0; w < 2; ++w) {
      self.wall_results_[w].assign(p.size(), WallResult{});
      self.wall_reported_[w].assign(p.size(), 0);
    }
  }
  results(self.pair_results_, self.pair_reported_, pair_result);
  for (int w = 0; w < 2; ++w) results(self.wall_results_[w], self.wall_reported_[w], wall_result);
}

void Simulation::write_state(std::ostream& out) const {
  Writer writer{out};
  writer(kStateTag);
  state_fields(writer, *this);
}

void Simulation::read_state(std::istream& in) {
  Reader reader{in};
  std::uint64_t tag = 0;
  reader(tag);
  if (tag != kStateTag) throw std::runtime_error("not an ellc dem checkpoint (bad state tag)");
  state_fields(reader, *this);
  prepare_derived_arrays();
}

}  // namespace ellc::engine
