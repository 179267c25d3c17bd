// Simulation::write_state / read_state: the checkpoint body. Everything the next step reads is
// stored, including the neighbour list and its reference positions, so that a restarted run
// rebuilds the list at the same steps and reproduces the uninterrupted run bit for bit.
// One field list (state_fields) serves both directions, so writer and reader cannot drift apart.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
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

// Adds up the bytes a field list stores (the size check of the arrays of records).
struct Counter {
  std::size_t bytes = 0;
  template <typename T>
  void operator()(const T& /*value*/) {
    if constexpr (std::is_same_v<T, Eigen::Vector3d>)
      bytes += 3 * sizeof(double);
    else
      bytes += sizeof(T);
  }
};

struct Reader {
  std::istream& in;
  bool species = true;  // false: a state from before species (ELLCDEM2), every particle species 0
  template <typename T>
  void operator()(T& value) {
    binary::get(in, value);
  }
  void operator()(std::vector<PairSlot>& pairs);
  void operator()(std::vector<WallContact>& walls);
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

constexpr std::uint64_t kStateTag = 0x454c4c43'44454d33ULL;  // "ELLCDEM3": with each particle's species
// "ELLCDEM2" (the shared history record, before species): read as one species, every particle 0.
constexpr std::uint64_t kStateTagOneSpecies = 0x454c4c43'44454d32ULL;

[[noreturn]] void corrupt(const std::string& what) { throw std::runtime_error("checkpoint is corrupt: " + what); }

std::string shortest(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

void check_finite(double value, const char* name) {
  if (!std::isfinite(value)) corrupt(std::string(name) + " = " + shortest(value) + " is not finite");
}

void check_history(const ContactHistory& h, const ContactCache& c, const std::string& where) {
  const Eigen::Map<const Eigen::Matrix<double, ContactHistory::kDoubles, 1>> values(&h.max_overlap);
  if (!values.allFinite() || !std::isfinite(c.last_overlap))
    corrupt("the contact history of " + where + " holds a non-finite number");
  if (h.max_overlap < 0.0 || h.spring_stiffness < 0.0 || (h.warm_valid != 0.0 && h.warm_valid != 1.0))
    corrupt("the contact history of " + where + " is out of range (largest overlap " + shortest(h.max_overlap) +
            ", spring stiffness " + shortest(h.spring_stiffness) + ", warm-start flag " + shortest(h.warm_valid) + ")");
}

// What a restarted run relies on: every array one entry per particle, positive semi-axes, mass and
// inertia, unit quaternions, finite motion, unique ids, dt > 0, walls in order, and pairs that name
// two existing particles by their slots and ids, sorted by key without repeats.
void validate_state(const ParticleSet& p, const std::vector<PairSlot>& pairs,
                    const std::array<std::vector<WallContact>, 2>& wall_history, const std::array<Wall, 2>& walls,
                    const EngineSettings& settings, double time, double skin) {
  check_finite(time, "the time");
  if (time < 0.0) corrupt("the time " + shortest(time) + " is negative");
  if (!(settings.dt > 0.0) || !std::isfinite(settings.dt))
    corrupt("the time step dt = " + shortest(settings.dt) + " (expected a finite dt > 0)");
  if (!(skin >= 0.0) || !std::isfinite(skin)) corrupt("the neighbour-list skin " + shortest(skin) + " is not >= 0");
  if (!settings.gravity.allFinite()) corrupt("the gravity is not finite");
  check_finite(settings.drag_rate, "the drag rate");
  for (const Wall& wall : walls) {
    check_finite(wall.position, "a wall position");
    check_finite(wall.velocity, "a wall velocity");
    check_finite(wall.work, "a wall's work");
    if (!wall.force.allFinite()) corrupt("a wall force is not finite");
  }
  if (walls[kBottomWall].side != 1 || walls[kTopWall].side != -1) corrupt("the walls' sides are not +1 and -1");
  if (!(walls[kBottomWall].position < walls[kTopWall].position))
    corrupt("the top wall (z = " + shortest(walls[kTopWall].position) +
            ") is not above the bottom wall (z = " + shortest(walls[kBottomWall].position) + ")");
  const std::size_t n = p.size();
  for (const std::size_t size :
       {p.semi_axes.size(), p.mass.size(), p.inertia.size(), p.mean_radius.size(), p.bounding_radius.size(),
        p.position.size(), p.orientation.size(), p.velocity.size(), p.angular_velocity.size(), p.force.size(),
        p.torque.size(), p.species.size(), wall_history[0].size(), wall_history[1].size()})
    if (size != n)
      corrupt("a particle array holds " + std::to_string(size) + " entries for " + std::to_string(n) + " particles");
  std::vector<std::uint32_t> ids = p.id;
  std::sort(ids.begin(), ids.end());
  if (const auto repeated = std::adjacent_find(ids.begin(), ids.end()); repeated != ids.end())
    corrupt("particle id " + std::to_string(*repeated) + " appears twice");
  for (std::size_t k = 0; k < n; ++k) {
    const std::string particle = "particle " + std::to_string(p.id[k]);
    const Eigen::Vector3d& axes = p.semi_axes[k];
    if (!axes.allFinite() || !(axes.minCoeff() > 0.0))
      corrupt(particle + " has semi-axes (" + shortest(axes.x()) + ", " + shortest(axes.y()) + ", " +
              shortest(axes.z()) + "), expected finite and > 0");
    if (!(p.mass[k] > 0.0) || !std::isfinite(p.mass[k]) || !p.inertia[k].allFinite() ||
        !(p.inertia[k].minCoeff() > 0.0))
      corrupt(particle + " has a mass or moment of inertia that is not finite and > 0");
    if (!(p.mean_radius[k] > 0.0) || !std::isfinite(p.mean_radius[k]) ||
        !(p.bounding_radius[k] >= axes.maxCoeff() * (1.0 - 1e-12)) || !std::isfinite(p.bounding_radius[k]))
      corrupt(particle + " has a mean or bounding radius that does not fit its semi-axes");
    const double norm = p.orientation[k].coeffs().norm();
    if (!(std::abs(norm - 1.0) <= 1e-6))
      corrupt(particle + " has an orientation quaternion of norm " + shortest(norm) + ", expected 1 (within 1e-6)");
    if (!p.position[k].allFinite() || !p.velocity[k].allFinite() || !p.angular_velocity[k].allFinite() ||
        !p.force[k].allFinite() || !p.torque[k].allFinite())
      corrupt(particle + " has a non-finite position, velocity, force or torque");
    // Between the walls (a body may touch one), and x, y within reach of the periodic box.
    const Eigen::Vector3d& x = p.position[k];
    const double reach = p.bounding_radius[k];
    if (!(x.z() >= walls[kBottomWall].position - reach && x.z() <= walls[kTopWall].position + reach) ||
        !(std::abs(x.x()) <= 1e100 && std::abs(x.y()) <= 1e100))
      corrupt(particle + " at (" + shortest(x.x()) + ", " + shortest(x.y()) + ", " + shortest(x.z()) +
              ") is outside the walls z = " + shortest(walls[kBottomWall].position) + " .. " +
              shortest(walls[kTopWall].position));
    for (int w = 0; w < 2; ++w)
      check_history(wall_history[w][k].history, wall_history[w][k].cache, particle + " on wall " + std::to_string(w));
  }
  for (std::size_t index = 0; index < pairs.size(); ++index) {
    const PairSlot& pair = pairs[index];
    const std::string where = "pair " + std::to_string(index);
    if (pair.i >= n || pair.j >= n || pair.i == pair.j)
      corrupt(where + " refers to particle slots " + std::to_string(pair.i) + " and " + std::to_string(pair.j) +
              " of " + std::to_string(n));
    if (!(p.id[pair.i] < p.id[pair.j]) || pair.key != pair_key(p.id[pair.i], p.id[pair.j]))
      corrupt(where + " does not match the ids of its particles");
    if (index > 0 && !(pairs[index - 1].key < pair.key)) corrupt(where + " is out of order or repeated");
    if (!pair.shift.allFinite()) corrupt(where + " has a non-finite periodic shift");
    check_history(pair.history, pair.cache, where);
  }
}

}  // namespace

void Reader::operator()(std::vector<PairSlot>& pairs) {
  Counter counter;
  PairSlot sample;
  pair_fields(counter, sample);
  binary::get(in, pairs, counter.bytes);
}

void Reader::operator()(std::vector<WallContact>& walls) {
  Counter counter;
  WallContact sample;
  history_fields(counter, sample.history, sample.cache);
  binary::get(in, walls, counter.bytes);
}

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
  if constexpr (std::is_same_v<Io, Reader>) {
    if (io.species)
      io(p.species);
    else
      p.species.assign(p.id.size(), 0);
  } else {
    io(p.species);
  }
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
    if constexpr (std::is_same_v<Io, Reader>) {
      if (static_cast<int>(result.regime) >= kRegimeCount) corrupt("a contact result names an unknown regime");
      if (!std::isfinite(result.released_work) || !std::isfinite(result.damping_dissipation) ||
          !std::isfinite(result.friction_dissipation))
        corrupt("a contact result holds a non-finite energy");
    }
  };
  const auto pair_result = [&io, &tally](auto& result) {
    io(result.force_on_j);
    io(result.torque_i);
    io(result.torque_j);
    tally(result);
    if constexpr (std::is_same_v<Io, Reader>)
      if (!result.force_on_j.allFinite() || !result.torque_i.allFinite() || !result.torque_j.allFinite())
        corrupt("a pair's contact force or torque is not finite");
  };
  const auto wall_result = [&io, &tally](auto& result) {
    io(result.force_on_wall);
    tally(result);
    if constexpr (std::is_same_v<Io, Reader>)
      if (!result.force_on_wall.allFinite()) corrupt("a wall contact's force is not finite");
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
  if constexpr (std::is_same_v<Io, Reader>)
    validate_state(p, self.pairs_, self.wall_history_, self.walls_, self.settings_, self.time_, self.skin_);
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
  if (tag != kStateTag && tag != kStateTagOneSpecies) corrupt("the simulation state does not start with its tag");
  reader.species = tag == kStateTag;
  state_fields(reader, *this);
  try {
    check_species();
  } catch (const std::invalid_argument& error) {
    corrupt(error.what());
  }
  prepare_derived_arrays();
  wall_stiffness_.fill(0.0);  // derived by the next step's accumulate(), as the servo expects
}

}  // namespace ellc::engine
