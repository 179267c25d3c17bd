#pragma once
// The DEM world: particles, two z walls, the neighbour list with its contact histories, and one
// velocity-Verlet step. Broad phase (broad_phase.hpp) here; narrow phase and contact model
// (src/ellc/contact/pair_contact.hpp), shared with LAMMPS; this class only orders them.
//
// Determinism: every contact is evaluated independently (in parallel) into its own slot of a
// result array; each particle then gathers its forces (in parallel) in the fixed order of the
// sorted pair list, and scalar totals are summed over fixed chunks of that list. The results
// therefore do not depend on the number of threads, bit for bit.

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_model.hpp"
#include "ellc/contact/contact_size.hpp"
#include "ellc/contact/pair_contact.hpp"
#include "ellc/engine/pair_map.hpp"
#include "ellc/engine/pair_partition.hpp"
#include "ellc/engine/particles.hpp"
#include "ellc/engine/settings.hpp"
#include "ellc/engine/thread_count.hpp"
#include "ellc/geometry/ellipsoid.hpp"

namespace ellc::engine {

// A non-finite or runaway velocity: names the particle (id) and the step.
class RunawayError : public std::runtime_error {
 public:
  RunawayError(const std::string& message, std::uint32_t particle_id, std::uint64_t step)
      : std::runtime_error(message), particle_id_(particle_id), step_(step) {}
  [[nodiscard]] std::uint32_t particle_id() const noexcept { return particle_id_; }
  [[nodiscard]] std::uint64_t step() const noexcept { return step_; }

 private:
  std::uint32_t particle_id_;
  std::uint64_t step_;
};

inline constexpr int kBottomWall = 0;
inline constexpr int kTopWall = 1;
inline constexpr int kRegimeCount = 5;  // Regime::separated .. Regime::unloading

// A particle's contact with one wall: the shared history record and the engine's cache.
struct WallContact {
  ContactHistory history;
  ContactCache cache;
};

struct ContactCounts {
  std::size_t particle_contacts = 0;  // particle–particle pairs with δ > 0
  std::size_t wall_contacts = 0;
  std::array<std::size_t, kRegimeCount> by_regime{};  // all contacts, by the law's regime
  std::uint64_t narrow_phase_failures = 0;            // since the start of the run
};

// How much of the current state rests on contacts beyond the law's range. The paper places the
// finite-deformation regime, outside its theory, at c_c/r̂ = 0.16–0.4 (Sec. 2.2) with r̂ the mean
// particle radius. Here c_c is the equivalent contact radius of eq. (9) at the contact's largest
// overlap δ_*, and r̂ the mean radius of the smaller particle of the pair (the particle's own
// against a wall): the stricter reading.
struct ValidityReport {
  double threshold = 0.16;
  std::size_t pair_contacts = 0;
  std::size_t pair_contacts_beyond = 0;
  double pair_force = 0.0;  // Σ |F| over pair contacts
  double pair_force_beyond = 0.0;
  std::size_t wall_contacts = 0;
  std::size_t wall_contacts_beyond = 0;
  double wall_force = 0.0;  // Σ |F| over wall contacts
  double wall_force_beyond = 0.0;
  double largest_ratio = 0.0;  // max c_c/r̂ over all contacts
};

// One contact of the last force evaluation, for outputs (Simulation::for_each_contact): the
// contacts ValidityReport and ContactCounts count, a pair of particles or a particle on a wall.
struct ContactView {
  int wall = -1;        // −1: a pair; kBottomWall or kTopWall: particle i against that wall
  std::uint32_t i = 0;  // particle slot (of a pair: the smaller id)
  std::uint32_t j = 0;  // the other particle's slot (pairs only)
  Eigen::Vector3d centre_i = Eigen::Vector3d::Zero();
  // Pairs: the centre of j's periodic image (j's centre + the pair's shift); walls: the contact point.
  Eigen::Vector3d other = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, i → j (particle → wall)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // on j (pairs) or on the wall, µN
  double normal_force = 0.0;                          // force · normal, µN (> 0 presses the bodies apart)
  double overlap = 0.0;                               // δ of the last evaluation, µm
  double max_overlap = 0.0;                           // δ_*, µm
  Regime regime = Regime::separated;
  double size_ratio = 0.0;  // c_c/r̂ as ValidityReport defines it (contact_size_ratio)
};

class Simulation {
 public:
  Simulation(const EngineSettings& settings, ParticleSet particles, const std::array<Wall, 2>& walls);

  // One velocity-Verlet step. Throws RunawayError (state left at the end of the step).
  void step();

  [[nodiscard]] const ParticleSet& particles() const noexcept { return particles_; }
  [[nodiscard]] const std::array<Wall, 2>& walls() const noexcept { return walls_; }
  // Wall motion is prescribed: the protocol sets velocities (and may place a wall between steps).
  void set_wall_velocity(int wall, double velocity) noexcept { walls_[wall].velocity = velocity; }
  void set_wall_position(int wall, double position);
  [[nodiscard]] EngineSettings& settings() noexcept { return settings_; }
  [[nodiscard]] const EngineSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] std::uint64_t step_count() const noexcept { return step_; }
  [[nodiscard]] double time() const noexcept { return time_; }
  [[nodiscard]] const std::vector<PairSlot>& pairs() const noexcept { return pairs_; }
  [[nodiscard]] std::uint64_t neighbour_rebuilds() const noexcept { return rebuilds_; }
  [[nodiscard]] double skin() const noexcept { return skin_; }  // the neighbour list's, µm
  // Threads the next step runs on (settings().adaptive_threads; a diagnostic).
  [[nodiscard]] int thread_count() const noexcept { return threads_; }
  // Pair evaluations since the start that a thread took from another thread's range of the pair
  // list (the threaded loop's load balancing; a diagnostic).
  [[nodiscard]] std::uint64_t pairs_taken_by_other_threads() const noexcept { return pairs_taken_by_other_threads_; }
  // Candidate pairs currently proven apart, whose test the next step skips (a diagnostic).
  [[nodiscard]] std::size_t pairs_proven_apart() const noexcept;

  // Observables (serial sums in slot order: deterministic).
  [[nodiscard]] double kinetic_energy() const noexcept;  // translational + rotational, pJ
  [[nodiscard]] double plastic_dissipation() const noexcept;
  // Energy the dashpots and sliding friction have dissipated since the start, pJ (ContactForce).
  [[nodiscard]] double damping_dissipation() const noexcept { return damping_dissipation_; }
  [[nodiscard]] double friction_dissipation() const noexcept { return friction_dissipation_; }
  // Elastic energy of the tangential springs, ½ k_t |ξ|², pJ.
  [[nodiscard]] double spring_energy() const noexcept;
  // Work the walls have done on the particles since the start, pJ (their sum is the plate work).
  [[nodiscard]] double wall_work(int wall) const noexcept { return walls_[wall].work; }
  // Elastic energy stored in the contacts: what the law would give back on full unloading, pJ.
  [[nodiscard]] double contact_elastic_energy() const noexcept;  // ∫F_law dδ minus what the law gives back, pJ
  [[nodiscard]] ContactCounts contact_counts() const noexcept;
  [[nodiscard]] ValidityReport validity(double threshold = 0.16) const noexcept;
  // Calls `visit` for every contact of the last force evaluation: the pairs in pair-list order,
  // then the floor's contacts and the plate's, each by particle slot. Read-only; for outputs.
  void for_each_contact(const std::function<void(const ContactView&)>& visit) const;
  // Static equilibrium: the mean magnitude of the particles' net contact force over the mean
  // magnitude of the contact forces (pair and wall contacts). 0 in exact equilibrium; the usual
  // quasi-static criterion is < 10⁻³. 1 when there are no contact forces at all.
  [[nodiscard]] double unbalanced_force_ratio() const noexcept;
  // Force the particles push a wall with, along the wall's outward direction, per box area (MPa).
  [[nodiscard]] double wall_pressure(int wall) const noexcept;
  [[nodiscard]] double gap() const noexcept { return walls_[kTopWall].position - walls_[kBottomWall].position; }
  [[nodiscard]] double porosity() const noexcept;
  [[nodiscard]] std::size_t wall_contact_count(int wall) const noexcept;
  // Σ k_n of the wall's contacts at the last force evaluation (µN/µm), for a servo's loop gain
  // (engine/servo.hpp). 0 before the first step after a restart.
  [[nodiscard]] double wall_stiffness(int wall) const noexcept { return wall_stiffness_[wall]; }
  [[nodiscard]] double highest_point() const noexcept;  // max z of the bounding spheres

  // Full state (particles, walls, contact histories, neighbour list, counters) for restart.
  void write_state(std::ostream& out) const;
  void read_state(std::istream& in);

 private:
  // What one contact evaluation reports to the sums of the step, pair or wall alike.
  struct ContactTally {
    double released_work = 0.0;  // plastic work of a contact that ended
    double damping_dissipation = 0.0;
    double friction_dissipation = 0.0;
    Regime regime = Regime::separated;
    bool contact = false;
    bool failed = false;
  };
  struct PairResult : ContactTally {
    Eigen::Vector3d force_on_j = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque_i = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque_j = Eigen::Vector3d::Zero();
  };
  struct WallResult : ContactTally {
    Eigen::Vector3d force_on_wall = Eigen::Vector3d::Zero();
    double normal_stiffness = 0.0;  // k_n (ContactForce), summed into wall_stiffness_; not in checkpoints
  };
  // A result slot is only written when this step has something to say (a contact, released
  // plastic work, a failure); a byte per slot (1 = written this step) says which slots are
  // current, so that the many empty ones are neither cleared nor read every step (the clearing
  // store alone missed the cache for ~2 % of a DEM step's cycles).
  template <typename Result>
  [[nodiscard]] static bool holds_something(const Result& result) noexcept {
    return result.contact || result.failed || result.released_work != 0.0 || result.friction_dissipation != 0.0;
  }

  template <typename Io, typename Self>
  static void state_fields(Io& io, Self& self);  // simulation_state.cpp
  void prepare_derived_arrays();                 // sphere flags (frames aligned), body frames, pair index
  void align_sphere_frames() noexcept;           // spheres: identity orientation, world-frame ω
  void index_pairs_by_particle();
  void forget_proven_separations();
  [[nodiscard]] bool proven_apart(std::size_t pair_index, double travel) const noexcept {
    return travel < clearance_budget_[pair_index];
  }
  void rebuild_neighbours();
  void refresh_body_frames() noexcept;
  void refresh_body_frame(std::size_t slot) noexcept;
  [[nodiscard]] bool kick_and_drift(double half_dt) noexcept;
  [[nodiscard]] std::size_t kick_and_check(double half_dt) noexcept;
  void kick_particle(std::size_t slot, double half_dt, const Eigen::Vector3d& gravity, double drag) noexcept;
  // The second half kick, given to compute_forces() so that threads kick each particle as soon
  // as its force is complete.
  struct SecondKick {
    bool apply = false;
    double half_dt = 0.0;
  };
  std::size_t compute_forces(SecondKick kick);
  std::size_t compute_forces_threaded(SecondKick kick);
  void evaluate_walls_of_range(std::size_t range);
  [[nodiscard]] bool kick_and_check_particle(std::size_t slot, double half_dt) noexcept;
  [[nodiscard]] std::uint64_t evaluate_pairs_in_order();
  // add_to_i / add_to_j: add the pair's force and torque to that particle right away (the thread
  // evaluating the pair is the only one that adds to it this step).
  void evaluate_pair(std::size_t index, bool add_to_i, bool add_to_j);
  void evaluate_walls_and_reset(std::size_t slot);
  void gather_pair_forces(std::size_t slot, std::size_t first_pair);
  // The first and last pair (list indices) of each particle; first > last: no pairs.
  struct PairSpan {
    std::uint32_t first = 1;
    std::uint32_t last = 0;
  };
  // The threaded pair loop's ranges (pair_partition.hpp): the one that holds pair `index`, a
  // block of a range taken by its owner (front) or another thread (back), and after the loop
  // the first pair of a range its owner did not evaluate.
  [[nodiscard]] int range_of_pair(std::size_t index) const noexcept;
  [[nodiscard]] bool claim_block(std::size_t range, bool from_front, std::size_t& block) noexcept;
  [[nodiscard]] std::size_t steal_point(int range) const noexcept;
  [[nodiscard]] std::size_t first_pair_not_added(std::size_t first, std::size_t last) const noexcept;
  static constexpr std::size_t kStealBlock = 64;  // pairs
  static constexpr std::size_t kClaimStride = 8;  // one claim per 64-byte cache line
  [[nodiscard]] bool pair_failed(std::size_t index) const noexcept {
    return pair_reported_[index] != 0 && pair_results_[index].failed;
  }
  struct ChunkSums {
    double released = 0.0;
    double damping = 0.0;
    double friction = 0.0;
  };
  // The pair list's tallies are summed in fixed chunks, so that threads give the same bits.
  static constexpr std::size_t kPairChunk = 4096;
  [[nodiscard]] std::size_t pair_chunk_count() const noexcept { return (pairs_.size() + kPairChunk - 1) / kPairChunk; }
  void tally_pair(std::size_t index, ChunkSums& sums) const noexcept;
  [[nodiscard]] ChunkSums sum_pair_chunk(std::size_t chunk) const noexcept;
  void accumulate(std::uint64_t pair_failures);
  [[noreturn]] void report_runaway(std::size_t first_bad) const;
  void choose_threads() noexcept;
  [[nodiscard]] bool parallel() const noexcept {
    return threads_ > 1 && particles_.size() > settings_.parallel_threshold;
  }

  EngineSettings settings_;
  ParticleSet particles_;
  std::array<Wall, 2> walls_;
  // One context per pair of species (S × S, row-major, symmetric) and per species on the walls:
  // the per-pair constants are looked up by the particles' species, never stored per particle.
  [[nodiscard]] const InteractionContext& pair_context(std::size_t i, std::size_t j) const noexcept {
    return pair_contexts_[particles_.species[i] * species_count_ + particles_.species[j]];
  }
  [[nodiscard]] const InteractionContext& wall_context(std::size_t slot) const noexcept {
    return wall_contexts_[particles_.species[slot]];
  }
  void check_species() const;  // every particle's species names a material of the settings
  std::size_t species_count_ = 1;
  std::vector<InteractionContext> pair_contexts_;  // particle–particle contacts
  std::vector<InteractionContext> wall_contexts_;  // particle–wall contacts (the walls' friction)
  std::vector<char> is_sphere_;
  std::vector<Eigen::Vector3d> omega_world_;
  std::vector<Ellipsoid> shapes_;                    // posed ellipsoids of this step (non-spheres only)
  std::vector<Eigen::Vector3d> reference_position_;  // at the last neighbour-list build
  // Proven separation (docs/engine.md, "Pairs proven apart"): travel_[k] bounds how far any point
  // of particle k has moved since the last neighbour-list build; a pair found apart with clearance
  // c along a fixed axis stays apart while travel_[i] + travel_[j] < clearance_budget_[pair],
  // which is set to (their travel then) + c. Not state: a pair without a budget is just tested.
  std::vector<double> travel_;
  std::vector<double> clearance_budget_;
  std::vector<PairSlot> pairs_;
  std::vector<PairSlot> spare_pairs_;  // storage for the next rebuild's list (no state)
  std::vector<PairResult> pair_results_;
  std::vector<std::uint8_t> pair_reported_;  // 1: pair_results_[k] is this step's; 0: empty
  // The pairs of each particle in pair-list order (CSR): entry = 2 × pair index + (particle is j).
  std::vector<std::uint32_t> pairs_of_particle_start_;
  std::vector<std::uint32_t> pairs_of_particle_;
  std::vector<PairSpan> pair_span_;  // per particle, from the same index
  // Which thread evaluates a particle's walls in the threaded loop: the owner of the range that
  // holds its first pair (a particle without pairs: by slot). Listed once per rebuild so that each
  // thread finds its particles by two binary searches instead of scanning all of them: the slots
  // with pairs in order of their first pair (and those first pairs), the slots without in order.
  std::vector<std::uint32_t> slots_by_first_pair_;
  std::vector<std::uint32_t> first_pair_of_listed_;
  std::vector<std::uint32_t> slots_without_pairs_;
  std::vector<ChunkSums> chunk_sums_;
  // The threaded pair loop's contiguous ranges: their first pairs this step, and their cuts,
  // balanced on the time each range took. Not state: only the speed depends on it.
  PairPartition partition_;
  std::vector<std::size_t> range_start_;
  std::vector<std::uint64_t> range_claims_;  // per range, at kClaimStride: blocks left (claim_block)
  std::vector<double> range_seconds_;
  std::uint64_t pairs_taken_by_other_threads_ = 0;
  std::array<std::vector<WallContact>, 2> wall_history_;  // per particle slot
  std::array<std::vector<WallResult>, 2> wall_results_;
  // 1: wall_results_[w][slot] is this step's; 0: empty, and then the wall contact is not active
  // (every step that leaves a wall history active reports it), so a particle far from the wall
  // is passed over without reading its history.
  std::array<std::vector<std::uint8_t>, 2> wall_reported_;
  double skin_ = 0.0;
  double released_work_ = 0.0;  // plastic work of deleted contacts
  double damping_dissipation_ = 0.0;
  double friction_dissipation_ = 0.0;
  std::uint64_t failures_ = 0;
  std::array<double, 2> wall_stiffness_{};  // Σ k_n per wall, summed in accumulate(); not state
  std::uint64_t step_ = 0;
  std::uint64_t rebuilds_ = 0;
  double time_ = 0.0;
  AdaptiveThreadCount thread_choice_;  // not state: only the speed depends on it
  int threads_ = 1;                    // of the current step's parallel loops
};

}  // namespace ellc::engine
