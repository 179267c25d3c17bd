#include "ellc/engine/simulation.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>

#include "ellc/assert.hpp"
#include "ellc/contact/contact_energy.hpp"
#include "ellc/contact/proven_apart.hpp"
#include "ellc/engine/broad_phase.hpp"
#include "ellc/engine/equilibrium.hpp"
#include "ellc/engine/invariants.hpp"
#include "ellc/engine/rigid_body.hpp"
#include "ellc/geometry/wall_contact.hpp"

#include <omp.h>

namespace ellc::engine {

namespace {

// The neighbour-list skin when the settings leave it at 0. 0.2 mean bounding radii halved the
// rebuilds of the bench_dem packing against 0.1 (10 → 5 in 300 steps, for 13 % more candidate
// pairs, each one distance test per step) and ran 6–12 % faster. Never so wide that the box stops
// holding 2 (2 R_max + skin), which the broad phase's minimum image needs, and never below the
// former 0.1 that the scenario reader's box check (`box.size`) guarantees room for. Only the cost
// and the rounding depend on it (a pair kept longer in the list keeps its warm start).
double default_skin(const ParticleSet& particles, const Box& box) noexcept {
  if (particles.size() == 0) return 0.0;
  double mean_bounding = 0.0;
  double largest = 0.0;
  for (double radius : particles.bounding_radius) {
    mean_bounding += radius;
    largest = std::max(largest, radius);
  }
  mean_bounding /= static_cast<double>(particles.size());
  const double room = 0.5 * std::min(box.lx, box.ly) - 2.0 * largest;
  return std::max(0.1 * mean_bounding, std::min(0.2 * mean_bounding, room));
}

// What an ended contact leaves behind: its plastic work (dissipated for good) and the energy
// still in its tangential spring (lost with it, booked with friction).
struct EndedContact {
  double plastic_work = 0.0;
  double spring_energy = 0.0;
};

// Ends a contact on separation. The cache keeps the sphere constants (they do not change) and the
// history its warm start (the separating axis just found is tested first next step).
EndedContact end_contact(ContactHistory& history, ContactCache& cache) noexcept {
  const EndedContact ended{plastic_work(cache.constants, history.max_overlap), history.spring_energy()};
  history.end_contact();
  cache.last_overlap = 0.0;
  return ended;
}

}  // namespace

Simulation::Simulation(const EngineSettings& settings, ParticleSet particles, const std::array<Wall, 2>& walls)
    : settings_(settings), particles_(std::move(particles)), walls_(walls) {
  choose_threads();
  const ContactSettings& contact = settings_.contact;
  const std::vector<Material> materials = species_materials(contact);
  species_count_ = materials.size();
  ContactModel wall_model = contact.model;
  wall_model.friction = contact.wall_friction;
  for (const Material& body_i : materials) {
    for (const Material& body_j : materials) pair_contexts_.push_back(make_interaction(contact.model, body_i, body_j));
    wall_contexts_.push_back(make_interaction(wall_model, body_i, contact.wall_material.value_or(body_i)));
  }
  const std::size_t count = particles_.size();
  if (particles_.species.empty()) particles_.species.assign(count, 0);  // one species
  check_species();
  prepare_derived_arrays();
  for (int wall = 0; wall < 2; ++wall) {
    wall_history_[wall].assign(count, WallContact{});
    wall_results_[wall].assign(count, WallResult{});
    wall_reported_[wall].assign(count, 0);
  }
  skin_ = settings_.skin > 0.0 ? settings_.skin : default_skin(particles_, settings_.box);
  rebuild_neighbours();
  refresh_body_frames();
  (void)compute_forces(SecondKick{});  // the forces of the first half kick
}

void Simulation::check_species() const {
  const auto& species = particles_.species;
  if (species.size() != particles_.size())
    throw std::invalid_argument("particle species: " + std::to_string(species.size()) + " entries for " +
                                std::to_string(particles_.size()) + " particles");
  for (std::size_t slot = 0; slot < species.size(); ++slot)
    if (species[slot] >= species_count_)
      throw std::invalid_argument("particle " + std::to_string(particles_.id[slot]) + " is of species " +
                                  std::to_string(species[slot]) + ", but the settings give " +
                                  std::to_string(species_count_) + " species (0 .. " +
                                  std::to_string(species_count_ - 1) + ")");
}

void Simulation::prepare_derived_arrays() {
  const std::size_t count = particles_.size();
  is_sphere_.resize(count);
  for (std::size_t slot = 0; slot < count; ++slot) {
    const auto& axes = particles_.semi_axes[slot];
    is_sphere_[slot] = axes.x() == axes.y() && axes.x() == axes.z();
  }
  align_sphere_frames();
  omega_world_.assign(count, Eigen::Vector3d::Zero());
  shapes_.assign(count, Ellipsoid(Eigen::Vector3d::Ones()));
  index_pairs_by_particle();
  forget_proven_separations();
}

// A sphere's orientation has no effect on its contacts or its motion (I is isotropic), so the
// engine does not track it: the sphere's body frame is the world frame, its orientation the
// identity, and its angular velocity the world one. Its step then needs no rotation (quaternion
// update, τ and ω between frames): 18 % faster against LAMMPS on spheres (docs/performance.md).
// A state with another orientation (a packing, an older checkpoint) keeps its world angular
// velocity; an aligned one is left bit for bit, so restarts stay exact.
void Simulation::align_sphere_frames() noexcept {
  auto& p = particles_;
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  for (std::size_t slot = 0; slot < p.size(); ++slot) {
    if (is_sphere_[slot] == 0 || p.orientation[slot].coeffs() == identity.coeffs()) continue;
    p.angular_velocity[slot] = p.orientation[slot] * p.angular_velocity[slot];
    p.orientation[slot] = identity;
  }
}

void Simulation::forget_proven_separations() {
  travel_.assign(particles_.size(), 0.0);
  clearance_budget_.assign(pairs_.size(), 0.0);  // travel ≥ 0: no pair is skipped until tested
}

void Simulation::index_pairs_by_particle() {
  const std::size_t count = particles_.size();
  pairs_of_particle_start_.assign(count + 1, 0);
  for (const PairSlot& pair : pairs_) {
    ++pairs_of_particle_start_[pair.i + 1];
    ++pairs_of_particle_start_[pair.j + 1];
  }
  for (std::size_t slot = 0; slot < count; ++slot) pairs_of_particle_start_[slot + 1] += pairs_of_particle_start_[slot];
  pairs_of_particle_.resize(2 * pairs_.size());
  std::vector<std::uint32_t> fill(pairs_of_particle_start_.begin(), pairs_of_particle_start_.end() - 1);
  for (std::size_t index = 0; index < pairs_.size(); ++index) {
    const auto entry = static_cast<std::uint32_t>(2 * index);
    pairs_of_particle_[fill[pairs_[index].i]++] = entry;
    pairs_of_particle_[fill[pairs_[index].j]++] = entry + 1;
  }
  pair_span_.assign(count, PairSpan{});
  for (std::size_t slot = 0; slot < count; ++slot) {
    const std::uint32_t begin = pairs_of_particle_start_[slot];
    const std::uint32_t end = pairs_of_particle_start_[slot + 1];
    if (begin < end) pair_span_[slot] = {pairs_of_particle_[begin] >> 1U, pairs_of_particle_[end - 1] >> 1U};
  }
  ELLC_ASSERT(invariants::valid_pair_index(pairs_, count, pairs_of_particle_start_, pairs_of_particle_),
              "per-particle pair index inconsistent with the pair list");
}

std::size_t Simulation::pairs_proven_apart() const noexcept {
  std::size_t count = 0;
  for (std::size_t index = 0; index < pairs_.size(); ++index)
    count += proven_apart(index, travel_[pairs_[index].i] + travel_[pairs_[index].j]) ? 1U : 0U;
  return count;
}

void Simulation::set_wall_position(int wall, double position) { walls_[wall].position = position; }

void Simulation::rebuild_neighbours() {
  wrap_positions(particles_, settings_.box);
  find_candidate_pairs(particles_, settings_.box, skin_, parallel(), spare_pairs_);
  released_work_ += carry_over_history(pairs_, spare_pairs_, parallel());
  std::swap(pairs_, spare_pairs_);  // the old list's storage serves the next rebuild
  // Only the flags are cleared: every reader of a result checks its flag first, and every step
  // writes the results it flags (clearing 104 bytes a pair took 0.2 ms a rebuild, serially).
  pair_results_.resize(pairs_.size());
  pair_reported_.assign(pairs_.size(), 0);
  index_pairs_by_particle();
  forget_proven_separations();
  reference_position_ = particles_.position;
  ++rebuilds_;
}

void Simulation::refresh_body_frames() noexcept {
  auto& p = particles_;
  const std::size_t count = p.size();
#pragma omp parallel for schedule(static) num_threads(threads_) if (parallel())
  for (std::size_t slot = 0; slot < count; ++slot) refresh_body_frame(slot);
}

void Simulation::refresh_body_frame(std::size_t slot) noexcept {
  auto& p = particles_;
  if (is_sphere_[slot] != 0) {
    omega_world_[slot] = p.angular_velocity[slot];  // its frame is the world frame
    return;
  }
  omega_world_[slot] = p.orientation[slot] * p.angular_velocity[slot];
  // In place (no temporary Ellipsoid and copy); the same bits as building it anew.
  if (shapes_[slot].semi_axes() == p.semi_axes[slot])
    shapes_[slot].set_pose(Pose{p.position[slot], p.orientation[slot]});
  else
    shapes_[slot] = Ellipsoid(p.semi_axes[slot], Pose{p.position[slot], p.orientation[slot]});
}

// The threads of the next step: all of omp_get_max_threads(), or the adaptive choice between one
// and all (thread_count.hpp) fed with the previous step's wall time.
void Simulation::choose_threads() noexcept {
  const int most = omp_get_max_threads();
  if (!settings_.adaptive_threads) {
    threads_ = most;
    return;
  }
  if (most != thread_choice_.most()) thread_choice_.reset(most);
  threads_ = thread_choice_.current();
}

void Simulation::step() {
  choose_threads();
  const auto start = std::chrono::steady_clock::now();
  const double half_dt = 0.5 * settings_.dt;
  const bool stale = kick_and_drift(half_dt);
  for (auto& wall : walls_) wall.position += settings_.dt * wall.velocity;
  ++step_;
  time_ += settings_.dt;
  if (stale) {
    rebuild_neighbours();
    refresh_body_frames();  // positions were wrapped into the box
  }
  std::array<double, 2> force_before{walls_[0].force.z(), walls_[1].force.z()};
  const std::size_t runaway = compute_forces(SecondKick{true, half_dt});
  // The walls moved by v dt under the average of the forces at both ends of the step (the same
  // trapezoid the two half kicks give the particles' kinetic energy).
  for (int w = 0; w < 2; ++w)
    walls_[w].work -= 0.5 * (force_before[w] + walls_[w].force.z()) * walls_[w].velocity * settings_.dt;
  if (settings_.adaptive_threads && !stale && particles_.size() > settings_.parallel_threshold)
    thread_choice_.record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (runaway < particles_.size()) report_runaway(runaway);
}

// First half kick, drift, the posed shapes of the new configuration, and whether any particle
// moved more than half the skin since the neighbour list was built.
bool Simulation::kick_and_drift(double half_dt) noexcept {
  const std::size_t count = particles_.size();
  const Eigen::Vector3d gravity = settings_.gravity;
  const double drag = settings_.drag_rate;
  const double dt = settings_.dt;
  const double limit_sq = 0.25 * skin_ * skin_;
  auto& p = particles_;
  bool stale = false;
#pragma omp parallel for schedule(static) reduction(|| : stale) num_threads(threads_) if (parallel())
  for (std::size_t slot = 0; slot < count; ++slot) {
    kick_particle(slot, half_dt, gravity, drag);
    const Eigen::Vector3d before = p.position[slot];
    p.position[slot] += dt * p.velocity[slot];
    if (is_sphere_[slot] == 0)  // a sphere's frame stays the world frame (align_sphere_frames)
      p.orientation[slot] = advance_orientation(p.orientation[slot], p.angular_velocity[slot], dt);
    // No point of the body moves more than the centre's step plus the rotation angle |ω| dt times
    // the bounding radius; the factors and the 1e-15 cover the rounding of the computed motion.
    const double turn = p.angular_velocity[slot].norm() * dt * (1.0 + 1e-9) + 1e-15;
    travel_[slot] += bounded_displacement((p.position[slot] - before).norm()) + turn * p.bounding_radius[slot];
    refresh_body_frame(slot);
    stale = stale || (p.position[slot] - reference_position_[slot]).squaredNorm() > limit_sq;
  }
  return stale;
}

void Simulation::kick_particle(std::size_t slot, double half_dt, const Eigen::Vector3d& gravity, double drag) noexcept {
  auto& p = particles_;
  p.velocity[slot] += half_dt * (p.force[slot] / p.mass[slot] + gravity - drag * p.velocity[slot]);
  Eigen::Vector3d& omega = p.angular_velocity[slot];
  if (is_sphere_[slot] != 0) {  // body frame = world frame, isotropic I: no rotation, no gyroscopic term
    omega += half_dt * (p.torque[slot].cwiseQuotient(p.inertia[slot]) - drag * omega);
    return;
  }
  const Eigen::Vector3d torque_body = p.orientation[slot].conjugate() * p.torque[slot];
  omega += half_dt * (angular_acceleration(p.inertia[slot], omega, torque_body) - drag * omega);
}

// Second half kick of every particle, on one thread; returns the first slot with a non-finite or
// runaway velocity (size() if none).
std::size_t Simulation::kick_and_check(double half_dt) noexcept {
  std::size_t first_bad = particles_.size();
  for (std::size_t slot = 0; slot < particles_.size(); ++slot)
    if (kick_and_check_particle(slot, half_dt) && slot < first_bad) first_bad = slot;
  return first_bad;
}

// Second half kick of one particle; whether its motion is now non-finite or runaway.
bool Simulation::kick_and_check_particle(std::size_t slot, double half_dt) noexcept {
  const auto& p = particles_;
  const double limit = settings_.max_speed;
  kick_particle(slot, half_dt, settings_.gravity, settings_.drag_rate);
  const double speed = p.velocity[slot].norm();
  const double spin_speed = p.angular_velocity[slot].norm() * p.bounding_radius[slot];
  return !std::isfinite(speed) || !std::isfinite(spin_speed) || !p.position[slot].allFinite() || speed > limit ||
         spin_speed > limit;
}

// Wall contacts per particle, then pair contacts per pair; with `kick.apply`, then each particle's
// second half kick. Returns the first slot whose motion the kick made non-finite or runaway
// (size() if none, or without the kick).
std::size_t Simulation::compute_forces(SecondKick kick) {
  const std::size_t count = particles_.size();
  chunk_sums_.assign(pair_chunk_count(), ChunkSums{});  // the pairs' tallies (sum_pair_chunk)
  if (parallel()) return compute_forces_threaded(kick);
  // One thread: each pair adds to its particles as it is evaluated, and its tallies to its chunk
  // while its result is still in cache. The walls go first and the pairs in list order: the
  // order every particle's sum and every chunk's tally has with threads too.
  for (std::size_t slot = 0; slot < count; ++slot) evaluate_walls_and_reset(slot);
  accumulate(evaluate_pairs_in_order());
  return kick.apply ? kick_and_check(kick.half_dt) : count;
}

// Every pair in list order, each adding to its particles and to its chunk's tallies as it is
// evaluated; returns the failures.
std::uint64_t Simulation::evaluate_pairs_in_order() {
  std::uint64_t failures = 0;
  for (std::size_t index = 0; index < pairs_.size(); ++index) {
    evaluate_pair(index, true, true);
    failures += pair_failed(index) ? 1U : 0U;
    tally_pair(index, chunk_sums_[index / kPairChunk]);
  }
  return failures;
}

int Simulation::range_of_pair(std::size_t index) const noexcept {
  int range = 0;
  while (range + 1 < partition_.ranges() && index >= range_start_[static_cast<std::size_t>(range) + 1]) ++range;
  return range;
}

// Threads (docs/engine.md, "The threaded pair loop"). Each thread owns one contiguous range of the
// pair list (pair_partition.hpp) and the particles whose first pair lies in it (a particle without
// pairs: by slot). It evaluates its particles' walls, which starts their sums, then works through
// its range from the front in blocks of kStealBlock pairs, doing what the one-thread loop does: a
// particle whose pairs all lie in the range gets their forces added in list order, and the
// tallies go to the pair chunks. A thread that runs out of work takes blocks from the back of
// another range (results only). So each range ends at a steal point s: its owner evaluated
// [start, s), other threads [s, end).
// After one barrier, in list order, as the one-thread loop would add them:
//  - a particle whose pairs lie in one range adds the results of its pairs from s on;
//  - a particle whose pairs straddle a cut adds all its pair results (gather_pair_forces);
//  - a pair chunk that one owner did not evaluate whole is tallied again from the results;
// and each particle, its force complete, takes its second half kick.
// Every sum is the one-thread loop's, in its order: the same bits for any thread count, cuts and
// steals. Three barriers a step: after the drift, after the pairs, at the end.
std::size_t Simulation::compute_forces_threaded(SecondKick kick) {
  const std::size_t count = particles_.size();
  const std::size_t pair_count = pairs_.size();
  if (partition_.ranges() != threads_) {
    if (settings_.fixed_pair_cuts.size() + 1 == static_cast<std::size_t>(threads_))
      partition_.fix(settings_.fixed_pair_cuts);
    else
      partition_.reset(threads_);
  }
  const auto ranges = static_cast<std::size_t>(threads_);
  range_start_.resize(ranges + 1);
  for (std::size_t k = 0; k <= ranges; ++k) range_start_[k] = partition_.first_pair(static_cast<int>(k), pair_count);
  // Per range, the blocks not yet taken, [front, back), packed as back << 32 | front; the ranges'
  // claims a cache line apart.
  range_claims_.assign(ranges * kClaimStride, 0);
  for (std::size_t k = 0; k < ranges; ++k) {
    const std::uint64_t blocks = (range_start_[k + 1] - range_start_[k] + kStealBlock - 1) / kStealBlock;
    range_claims_[k * kClaimStride] = blocks << 32U;
  }
  range_seconds_.assign(ranges, 0.0);
  std::uint64_t failures = 0;
  std::uint64_t taken = 0;  // pairs evaluated by a thread that does not own their range
  std::size_t first_bad = count;
  int team_size = threads_;
#pragma omp parallel num_threads(threads_) reduction(+ : failures, taken) reduction(min : first_bad)
  {
    // A team smaller than asked for would leave ranges without an owner. It does not happen
    // without nesting, but if it did, every pair is evaluated after the region.
    const bool team_complete = omp_get_num_threads() == threads_;
    if (omp_get_thread_num() == 0) team_size = omp_get_num_threads();
    if (!team_complete) {
#pragma omp for schedule(static)
      for (std::size_t slot = 0; slot < count; ++slot) evaluate_walls_and_reset(slot);
    } else {
      const auto own = static_cast<std::size_t>(omp_get_thread_num());
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t slot = 0; slot < count; ++slot)
        if (owner_of_particle(slot) == own) evaluate_walls_and_reset(slot);
      const std::size_t lo = range_start_[own];
      const std::size_t hi = range_start_[own + 1];
      // The chunks that lie in this range alone (others' owners write the rest).
      const std::size_t first_chunk = (lo + kPairChunk - 1) / kPairChunk;
      const std::size_t end_chunk = hi == pair_count ? chunk_sums_.size() : hi / kPairChunk;
      std::size_t block = 0;
      while (claim_block(own, true, block)) {
        const std::size_t end = std::min(hi, lo + (block + 1) * kStealBlock);
        for (std::size_t index = lo + block * kStealBlock; index < end; ++index) {
          const PairSpan span_i = pair_span_[pairs_[index].i];
          const PairSpan span_j = pair_span_[pairs_[index].j];
          evaluate_pair(index, span_i.first >= lo && span_i.last < hi, span_j.first >= lo && span_j.last < hi);
          failures += pair_failed(index) ? 1U : 0U;
          const std::size_t chunk = index / kPairChunk;
          if (chunk >= first_chunk && chunk < end_chunk)
            tally_pair(index, chunk_sums_[chunk]);  // redone below if stolen from
        }
      }
      range_seconds_[own] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      for (std::size_t other = (own + 1) % ranges; other != own; other = (other + 1) % ranges) {
        while (claim_block(other, false, block)) {
          const std::size_t first = range_start_[other] + block * kStealBlock;
          const std::size_t end = std::min(range_start_[other + 1], first + kStealBlock);
          for (std::size_t index = first; index < end; ++index) {
            evaluate_pair(index, false, false);
            failures += pair_failed(index) ? 1U : 0U;
          }
          taken += end - first;
        }
      }
#pragma omp barrier
#pragma omp for schedule(static) nowait
      for (std::size_t chunk = 0; chunk < chunk_sums_.size(); ++chunk) {
        const std::size_t first = chunk * kPairChunk;
        const std::size_t last = std::min(pair_count, first + kPairChunk) - 1;
        const int range = range_of_pair(first);
        if (range != range_of_pair(last) || last >= steal_point(range)) chunk_sums_[chunk] = sum_pair_chunk(chunk);
      }
#pragma omp for schedule(static) nowait
      for (std::size_t slot = 0; slot < count; ++slot) {
        const PairSpan span = pair_span_[slot];
        if (span.first <= span.last) {
          const int range = range_of_pair(span.first);
          if (range != range_of_pair(span.last))
            gather_pair_forces(slot, 0);
          else if (span.last >= steal_point(range))
            gather_pair_forces(slot, steal_point(range));
        }
        if (kick.apply && kick_and_check_particle(slot, kick.half_dt) && slot < first_bad) first_bad = slot;
      }
    }
  }
  if (team_size != threads_) {  // the one-thread loop's pairs and kicks (not seen in practice)
    chunk_sums_.assign(pair_chunk_count(), ChunkSums{});
    accumulate(evaluate_pairs_in_order());
    return kick.apply ? kick_and_check(kick.half_dt) : count;
  }
  // Each range's time as if its owner had evaluated all of it, at the pace it kept.
  for (std::size_t k = 0; k < ranges; ++k) {
    const auto owned = static_cast<double>(steal_point(static_cast<int>(k)) - range_start_[k]);
    const auto all = static_cast<double>(range_start_[k + 1] - range_start_[k]);
    if (owned > 0.0) range_seconds_[k] *= all / owned;
  }
  partition_.record(range_seconds_);
  pairs_taken_by_other_threads_ += taken;
  accumulate(failures);
  return kick.apply ? first_bad : count;
}

// The thread that evaluates particle `slot`'s walls in the threaded loop: the owner of the range of
// its first pair, or for a particle without pairs one by slot.
std::size_t Simulation::owner_of_particle(std::size_t slot) const noexcept {
  const PairSpan span = pair_span_[slot];
  if (span.first <= span.last) return static_cast<std::size_t>(range_of_pair(span.first));
  return slot * static_cast<std::size_t>(partition_.ranges()) / particles_.size();
}

// Takes the next block of range `range` from its front (its owner) or its back (another thread);
// false when none is left.
bool Simulation::claim_block(std::size_t range, bool from_front, std::size_t& block) noexcept {
  std::atomic_ref<std::uint64_t> claims(range_claims_[range * kClaimStride]);
  std::uint64_t seen = claims.load(std::memory_order_relaxed);
  while (true) {
    const std::uint64_t front = seen & 0xffffffffU;
    const std::uint64_t back = seen >> 32U;
    if (front >= back) return false;
    const std::uint64_t wanted = from_front ? seen + 1 : seen - (std::uint64_t{1} << 32U);
    if (claims.compare_exchange_weak(seen, wanted, std::memory_order_relaxed)) {
      block = from_front ? front : back - 1;
      return true;
    }
  }
}

// After the threaded pair loop: the first pair of range `range` its owner did not evaluate.
std::size_t Simulation::steal_point(int range) const noexcept {
  const auto k = static_cast<std::size_t>(range);
  const std::uint64_t front = range_claims_[k * kClaimStride] & 0xffffffffU;
  return std::min(range_start_[k + 1], range_start_[k] + front * kStealBlock);
}

// Wall contacts of one particle; also starts the particle's force and torque sums with them.
void Simulation::evaluate_walls_and_reset(std::size_t slot) {
  auto& p = particles_;
  const Ellipsoid* shape = is_sphere_[slot] == 0 ? &shapes_[slot] : nullptr;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  const BodyMotion motion{p.velocity[slot], omega_world_[slot], p.mass[slot]};
  for (int w = 0; w < 2; ++w) {
    const Wall& wall = walls_[w];
    std::uint8_t& reported = wall_reported_[w][slot];
    const double reach = p.bounding_radius[slot] - wall.side * (p.position[slot].z() - wall.position);
    if (reach <= 0.0 && reported == 0) continue;  // far from this wall and not in contact (most particles)
    ContactHistory& history = wall_history_[w][slot].history;
    ContactCache& cache = wall_history_[w][slot].cache;
    WallResult& result = wall_results_[w][slot];
    result = WallResult{};
    reported = 1;  // cleared below if the result stays empty
    PairSolution solution;
    if (reach > 0.0) {
      const BodyRef body{p.semi_axes[slot], p.position[slot], p.orientation[slot], p.mean_radius[slot], shape};
      solution = solve_wall(body, WallPlane{wall.position, wall.side}, is_sphere_[slot] != 0, history, cache,
                            wall_context(slot));
    }
    if (solution.status == PairStatus::failed) {
      result.failed = true;
      continue;
    }
    if (solution.status == PairStatus::separated || solution.law.regime == Regime::separated) {
      if (solution.status == PairStatus::separated && history.active()) {
        const EndedContact ended = end_contact(history, cache);
        result.released_work = ended.plastic_work;
        result.friction_dissipation = ended.spring_energy;
      }
      if (solution.status == PairStatus::contact)
        result.contact = true;  // overlapping below δ_p: no force, history kept
      reported = holds_something(result) ? 1 : 0;
      continue;
    }
    const WallForces on_wall =
        wall_forces(solution, p.position[slot], motion, wall.velocity, wall_context(slot), settings_.dt, history);
    force -= on_wall.contact.on_j;
    torque -= on_wall.lever_cross_force;
    result.force_on_wall = on_wall.contact.on_j;
    result.normal_stiffness = on_wall.contact.normal_stiffness;
    result.damping_dissipation = on_wall.contact.damping_dissipation;
    result.friction_dissipation = on_wall.contact.friction_dissipation;
    result.regime = solution.law.regime;
    result.contact = true;
  }
  p.force[slot] = force;
  p.torque[slot] = torque;
}

void Simulation::evaluate_pair(std::size_t index, bool add_to_i, bool add_to_j) {
  auto& p = particles_;
  PairSlot& pair = pairs_[index];
  pair_reported_[index] = 0;
  const std::uint32_t i = pair.i;
  const std::uint32_t j = pair.j;
  const double travel = travel_[i] + travel_[j];
  if (proven_apart(index, travel)) return;  // the test below would find the pair apart too
  ContactHistory& history = pair.history;
  ContactCache& cache = pair.cache;
  const Eigen::Vector3d centre_j = p.position[j] + pair.shift;
  const double reach = p.bounding_radius[i] + p.bounding_radius[j];
  PairSolution solution;
  const double distance_sq = (centre_j - p.position[i]).squaredNorm();
  if (distance_sq < reach * reach) {
    // shapes_ holds posed ellipsoids for non-spheres only (a sphere meeting an ellipsoid is
    // posed on demand by the adapter, and never takes the separating-axis shortcut).
    const BodyRef body_i{p.semi_axes[i], p.position[i], p.orientation[i], p.mean_radius[i],
                         is_sphere_[i] == 0 ? &shapes_[i] : nullptr};
    const BodyRef body_j{p.semi_axes[j], centre_j, p.orientation[j], p.mean_radius[j],
                         is_sphere_[j] == 0 ? &shapes_[j] : nullptr};
    solution = solve_pair(body_i, body_j, is_sphere_[i] != 0 && is_sphere_[j] != 0, history, cache, pair_context(i, j));
  } else {
    solution.clearance = std::sqrt(distance_sq) - reach;  // bounding spheres apart
  }
  PairResult& result = pair_results_[index];
  if (solution.status == PairStatus::failed) {
    result = PairResult{};
    result.failed = true;
    pair_reported_[index] = 1;
    return;
  }
  if (solution.status == PairStatus::separated) {
    if (history.active()) {
      const EndedContact ended = end_contact(history, cache);
      if (ended.plastic_work != 0.0 || ended.spring_energy != 0.0) {
        result = PairResult{};
        result.released_work = ended.plastic_work;
        result.friction_dissipation = ended.spring_energy;
        pair_reported_[index] = 1;
      }
    }
    const double usable = usable_clearance(solution.clearance, reach);
    if (settings_.skip_proven_separated && usable > 0.0) clearance_budget_[index] = travel + usable;
    return;
  }
  result = PairResult{};
  pair_reported_[index] = 1;
  result.contact = true;
  result.regime = solution.law.regime;
  if (solution.law.regime != Regime::separated) {  // else overlapping below δ_p: no force
    const PairForces forces =
        pair_forces(solution, p.position[i], BodyMotion{p.velocity[i], omega_world_[i], p.mass[i]}, centre_j,
                    BodyMotion{p.velocity[j], omega_world_[j], p.mass[j]}, pair_context(i, j), settings_.dt, history);
    result.force_on_j = forces.contact.on_j;
    result.torque_i = forces.torque_on_i;
    result.torque_j = forces.torque_on_j;
    result.damping_dissipation = forces.contact.damping_dissipation;
    result.friction_dissipation = forces.contact.friction_dissipation;
  }
  // The operations of gather_pair_forces(), zeros included (they can turn -0 into +0).
  if (add_to_i) {
    p.force[i] -= result.force_on_j;
    p.torque[i] += result.torque_i;
  }
  if (add_to_j) {
    p.force[j] += result.force_on_j;
    p.torque[j] += result.torque_j;
  }
}

// Adds the results of particle `slot`'s pairs from pair `first_pair` on to its force and torque,
// in pair-list order: the order in which the one-thread loop adds them (after the threaded pair
// loop, for the pairs its owner did not add).
void Simulation::gather_pair_forces(std::size_t slot, std::size_t first_pair) {
  auto& p = particles_;
  Eigen::Vector3d force = p.force[slot];
  Eigen::Vector3d torque = p.torque[slot];
  for (std::uint32_t k = pairs_of_particle_start_[slot]; k < pairs_of_particle_start_[slot + 1]; ++k) {
    const std::uint32_t entry = pairs_of_particle_[k];
    if ((entry >> 1U) < first_pair) continue;
    if (pair_reported_[entry >> 1U] == 0) continue;
    const PairResult& result = pair_results_[entry >> 1U];
    if (!result.contact) continue;
    if ((entry & 1U) == 0U) {
      force -= result.force_on_j;
      torque += result.torque_i;
    } else {
      force += result.force_on_j;
      torque += result.torque_j;
    }
  }
  p.force[slot] = force;
  p.torque[slot] = torque;
}

// Adds pair `index`'s tallies of this step to `sums`.
void Simulation::tally_pair(std::size_t index, ChunkSums& sums) const noexcept {
  if (pair_reported_[index] == 0) return;
  const PairResult& result = pair_results_[index];
  sums.released += result.released_work;
  sums.damping += result.damping_dissipation;
  sums.friction += result.friction_dissipation;
}

// The tallies of one fixed chunk of the pair list, summed in list order.
Simulation::ChunkSums Simulation::sum_pair_chunk(std::size_t chunk) const noexcept {
  ChunkSums sums;
  const std::size_t end = std::min(pairs_.size(), (chunk + 1) * kPairChunk);
  for (std::size_t index = chunk * kPairChunk; index < end; ++index) tally_pair(index, sums);
  return sums;
}

// The walls' forces and stiffnesses, and the scalar totals of the step: the walls in slot order,
// then the pair chunks' sums (chunk_sums_, each summed in list order) in order: the same bits
// for any thread count. `pair_failures` counts the failed pairs of the step.
void Simulation::accumulate(std::uint64_t pair_failures) {
  for (auto& wall : walls_) wall.force.setZero();
  wall_stiffness_.fill(0.0);
  for (int w = 0; w < 2; ++w) {
    const auto& results = wall_results_[w];
    for (std::size_t slot = 0; slot < results.size(); ++slot) {
      if (wall_reported_[w][slot] == 0) continue;
      walls_[w].force += results[slot].force_on_wall;
      wall_stiffness_[w] += results[slot].normal_stiffness;
      released_work_ += results[slot].released_work;
      damping_dissipation_ += results[slot].damping_dissipation;
      friction_dissipation_ += results[slot].friction_dissipation;
      failures_ += results[slot].failed ? 1U : 0U;
    }
  }
  for (const ChunkSums& sums : chunk_sums_) {
    released_work_ += sums.released;
    damping_dissipation_ += sums.damping;
    friction_dissipation_ += sums.friction;
  }
  failures_ += pair_failures;
}

void Simulation::report_runaway(std::size_t first_bad) const {
  const auto& p = particles_;
  const auto text = [](double value) {  // shortest round-trip form: 1e+308, not 309 digits
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
  };
  const double limit = settings_.max_speed;
  const double speed = p.velocity[first_bad].norm();
  const double spin = p.angular_velocity[first_bad].norm();
  const double spin_speed = spin * p.bounding_radius[first_bad];  // the fastest surface point, relative to the centre
  std::string what;
  if (!std::isfinite(speed) || !std::isfinite(spin_speed) || !p.position[first_bad].allFinite())
    what = "a non-finite position, velocity or angular velocity";
  else if (spin_speed > limit && spin_speed >= speed)
    what = "a runaway spin: |omega| = " + text(spin) + " rad/µs moves its surface at " + text(spin_speed) +
           " µm/µs (translational speed " + text(speed) + " µm/µs; limit max_speed = " + text(limit) + " µm/µs)";
  else
    what = "a runaway velocity " + text(speed) + " µm/µs (surface speed of its spin " + text(spin_speed) +
           " µm/µs; limit max_speed = " + text(limit) + " µm/µs)";
  throw RunawayError("particle " + std::to_string(p.id[first_bad]) + " has " + what + " at step " +
                         std::to_string(step_) + " (t = " + text(time_) +
                         " µs); try a smaller time step or a lower wall speed",
                     p.id[first_bad], step_);
}

double Simulation::kinetic_energy() const noexcept {
  double energy = 0.0;
  const auto& p = particles_;
  for (std::size_t slot = 0; slot < p.size(); ++slot) {
    const Eigen::Vector3d& omega = p.angular_velocity[slot];
    energy +=
        0.5 * p.mass[slot] * p.velocity[slot].squaredNorm() + 0.5 * omega.dot(p.inertia[slot].cwiseProduct(omega));
  }
  return energy;
}

double Simulation::plastic_dissipation() const noexcept {
  double energy = released_work_;
  const auto remaining = [](const ContactHistory& h, const ContactCache& c) {
    return h.active() ? plastic_work(c.constants, h.max_overlap) : 0.0;
  };
  for (const auto& pair : pairs_) energy += remaining(pair.history, pair.cache);
  for (const auto& walls : wall_history_)
    for (const auto& wall : walls) energy += remaining(wall.history, wall.cache);
  return energy;
}

double Simulation::contact_elastic_energy() const noexcept {
  double energy = 0.0;
  const auto stored = [](const ContactHistory& h, const ContactCache& c) {
    return h.active() ? recoverable_energy(c.constants, c.last_overlap, h.max_overlap) : 0.0;
  };
  for (const auto& pair : pairs_) energy += stored(pair.history, pair.cache);
  for (const auto& walls : wall_history_)
    for (const auto& wall : walls) energy += stored(wall.history, wall.cache);
  return energy;
}

double Simulation::spring_energy() const noexcept {
  double energy = 0.0;
  for (const auto& pair : pairs_) energy += pair.history.spring_energy();
  for (const auto& walls : wall_history_)
    for (const auto& wall : walls) energy += wall.history.spring_energy();
  return energy;
}

ValidityReport Simulation::validity(double threshold) const noexcept {
  ValidityReport report;
  report.threshold = threshold;
  const auto& p = particles_;
  for (std::size_t index = 0; index < pairs_.size(); ++index) {
    if (pair_reported_[index] == 0 || !pair_results_[index].contact) continue;
    const PairSlot& pair = pairs_[index];
    const double ratio = contact_size_ratio(pair.cache.constants, pair.history.max_overlap,
                                            std::min(p.mean_radius[pair.i], p.mean_radius[pair.j]));
    const double force = pair_results_[index].force_on_j.norm();
    ++report.pair_contacts;
    report.pair_force += force;
    report.largest_ratio = std::max(report.largest_ratio, ratio);
    if (ratio > threshold) {
      ++report.pair_contacts_beyond;
      report.pair_force_beyond += force;
    }
  }
  for (int w = 0; w < 2; ++w)
    for (std::size_t slot = 0; slot < wall_results_[w].size(); ++slot) {
      if (wall_reported_[w][slot] == 0 || !wall_results_[w][slot].contact) continue;
      const WallContact& wall = wall_history_[w][slot];
      const double ratio = contact_size_ratio(wall.cache.constants, wall.history.max_overlap, p.mean_radius[slot]);
      const double force = wall_results_[w][slot].force_on_wall.norm();
      ++report.wall_contacts;
      report.wall_force += force;
      report.largest_ratio = std::max(report.largest_ratio, ratio);
      if (ratio > threshold) {
        ++report.wall_contacts_beyond;
        report.wall_force_beyond += force;
      }
    }
  return report;
}

void Simulation::for_each_contact(const std::function<void(const ContactView&)>& visit) const {
  const auto& p = particles_;
  for (std::size_t index = 0; index < pairs_.size(); ++index) {
    if (pair_reported_[index] == 0 || !pair_results_[index].contact) continue;
    const PairSlot& pair = pairs_[index];
    ContactView view;
    view.i = pair.i;
    view.j = pair.j;
    view.centre_i = p.position[pair.i];
    view.other = p.position[pair.j] + pair.shift;
    // Two spheres meet along their centre line; any other pair along the common normal the
    // narrow phase stored as its warm start.
    const bool spheres = is_sphere_[pair.i] != 0 && is_sphere_[pair.j] != 0;
    const auto& n = pair.history.warm_normal;
    view.normal = !spheres && pair.history.warm_valid != 0.0 ? Eigen::Vector3d(n[0], n[1], n[2]).normalized()
                                                             : (view.other - view.centre_i).normalized();
    view.force = pair_results_[index].force_on_j;
    view.normal_force = view.force.dot(view.normal);
    view.overlap = pair.cache.last_overlap;
    view.max_overlap = pair.history.max_overlap;
    view.regime = pair_results_[index].regime;
    view.size_ratio = contact_size_ratio(pair.cache.constants, pair.history.max_overlap,
                                         std::min(p.mean_radius[pair.i], p.mean_radius[pair.j]));
    visit(view);
  }
  for (int w = 0; w < 2; ++w)
    for (std::size_t slot = 0; slot < wall_results_[w].size(); ++slot) {
      if (wall_reported_[w][slot] == 0 || !wall_results_[w][slot].contact) continue;
      const WallContact& wall = wall_history_[w][slot];
      ContactView view;
      view.wall = w;
      view.i = view.j = static_cast<std::uint32_t>(slot);
      view.centre_i = p.position[slot];
      // The point the wall force acts at, as the contact layer finds it (closed form for a flat).
      if (is_sphere_[slot] != 0) {
        view.other = Eigen::Vector3d(p.position[slot].x(), p.position[slot].y(), walls_[w].position);
      } else {
        const Ellipsoid posed(p.semi_axes[slot], Pose{p.position[slot], p.orientation[slot]});
        view.other = wall_contact(posed, Plane{Eigen::Vector3d(0.0, 0.0, walls_[w].position),
                                               Eigen::Vector3d(0.0, 0.0, walls_[w].side)})
                         .geometry.point;
      }
      view.normal = Eigen::Vector3d(0.0, 0.0, -walls_[w].side);
      view.force = wall_results_[w][slot].force_on_wall;
      view.normal_force = view.force.dot(view.normal);
      view.overlap = wall.cache.last_overlap;
      view.max_overlap = wall.history.max_overlap;
      view.regime = wall_results_[w][slot].regime;
      view.size_ratio = contact_size_ratio(wall.cache.constants, wall.history.max_overlap, p.mean_radius[slot]);
      visit(view);
    }
}

double Simulation::unbalanced_force_ratio() const noexcept {
  const auto& p = particles_;
  double net = 0.0;
  for (std::size_t slot = 0; slot < p.size(); ++slot) net += p.force[slot].norm();  // contact forces only
  double contact = 0.0;
  std::size_t contacts = 0;
  for (std::size_t index = 0; index < pair_results_.size(); ++index) {
    if (pair_reported_[index] == 0 || !pair_results_[index].contact) continue;
    contact += pair_results_[index].force_on_j.norm();
    ++contacts;
  }
  for (int w = 0; w < 2; ++w)
    for (std::size_t slot = 0; slot < wall_results_[w].size(); ++slot) {
      if (wall_reported_[w][slot] == 0 || !wall_results_[w][slot].contact) continue;
      contact += wall_results_[w][slot].force_on_wall.norm();
      ++contacts;
    }
  return engine::unbalanced_force_ratio(net, p.size(), contact, contacts);
}

ContactCounts Simulation::contact_counts() const noexcept {
  ContactCounts counts;
  for (std::size_t index = 0; index < pair_results_.size(); ++index) {
    if (pair_reported_[index] == 0 || !pair_results_[index].contact) continue;
    ++counts.particle_contacts;
    ++counts.by_regime[static_cast<std::size_t>(pair_results_[index].regime)];
  }
  for (int w = 0; w < 2; ++w)
    for (std::size_t slot = 0; slot < wall_results_[w].size(); ++slot) {
      if (wall_reported_[w][slot] == 0 || !wall_results_[w][slot].contact) continue;
      ++counts.wall_contacts;
      ++counts.by_regime[static_cast<std::size_t>(wall_results_[w][slot].regime)];
    }
  counts.narrow_phase_failures = failures_;
  return counts;
}

double Simulation::wall_pressure(int wall) const noexcept {
  return -walls_[wall].side * walls_[wall].force.z() / (settings_.box.lx * settings_.box.ly);
}

double Simulation::porosity() const noexcept {
  const double volume = settings_.box.lx * settings_.box.ly * gap();
  return volume > 0.0 ? 1.0 - particles_.total_volume() / volume : 1.0;
}

std::size_t Simulation::wall_contact_count(int wall) const noexcept {
  std::size_t count = 0;
  for (std::size_t slot = 0; slot < wall_results_[wall].size(); ++slot)
    count += wall_reported_[wall][slot] != 0 && wall_results_[wall][slot].contact ? 1U : 0U;
  return count;
}

double Simulation::highest_point() const noexcept {
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t slot = 0; slot < particles_.size(); ++slot)
    top = std::max(top, particles_.position[slot].z() + particles_.bounding_radius[slot]);
  return top;
}

}  // namespace ellc::engine
