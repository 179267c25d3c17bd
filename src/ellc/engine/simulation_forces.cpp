// The step's forces (Simulation::compute_forces): wall contacts per particle, pair contacts per
// pair, and the sums of both into each particle's force and the step's tallies, on one thread or
// in the threaded pair loop of owned ranges (docs/engine.md, "One step" and "The threaded pair
// loop"). The rest of the step and the observables are in simulation.cpp.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "ellc/contact/contact_energy.hpp"
#include "ellc/contact/proven_apart.hpp"
#include "ellc/engine/simulation.hpp"

#include <omp.h>

namespace ellc::engine {

namespace {

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
  // The cuts range_start_[1 … ranges − 1] at or before `index` (a binary search: called per
  // particle after the loop, so a linear scan would cost every thread O(particles) on many cores).
  const auto cuts_begin = range_start_.begin() + 1;
  const auto cuts_end = range_start_.begin() + partition_.ranges();
  return static_cast<int>(std::upper_bound(cuts_begin, cuts_end, index) - cuts_begin);
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
    // A team smaller than asked for (a nested region, OMP_DYNAMIC) would leave ranges without an
    // owner: then every pair is evaluated after the region (tested).
    const bool team_complete = omp_get_num_threads() == threads_;
    if (omp_get_thread_num() == 0) team_size = omp_get_num_threads();
    if (!team_complete) {
#pragma omp for schedule(static)
      for (std::size_t slot = 0; slot < count; ++slot) evaluate_walls_and_reset(slot);
    } else {
      const auto own = static_cast<std::size_t>(omp_get_thread_num());
      const auto start = std::chrono::steady_clock::now();
      evaluate_walls_of_range(own);
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
        if (first_pair_not_added(first, last) <= last) chunk_sums_[chunk] = sum_pair_chunk(chunk);
      }
#pragma omp for schedule(static) nowait
      for (std::size_t slot = 0; slot < count; ++slot) {
        const PairSpan span = pair_span_[slot];
        if (span.first <= span.last) {
          const std::size_t from = first_pair_not_added(span.first, span.last);
          if (from <= span.last) gather_pair_forces(slot, from);
        }
        if (kick.apply && kick_and_check_particle(slot, kick.half_dt) && slot < first_bad) first_bad = slot;
      }
    }
  }
  if (team_size != threads_) {  // the one-thread loop's pairs and kicks
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

// The walls of the particles whose first pair lies in range `range`, and of the particles without
// pairs whose slot s has s × ranges / particles = range. Each particle's walls are per-slot state,
// so the order does not matter; the owner must only be the same thread that adds the particle's
// pair forces in its range.
void Simulation::evaluate_walls_of_range(std::size_t range) {
  const auto listed = [&](std::size_t k) {
    return static_cast<std::size_t>(std::lower_bound(first_pair_of_listed_.begin(), first_pair_of_listed_.end(),
                                                     static_cast<std::uint32_t>(range_start_[k])) -
                                    first_pair_of_listed_.begin());
  };
  const std::size_t last_range = static_cast<std::size_t>(partition_.ranges()) - 1;
  const std::size_t begin = range == 0 ? 0 : listed(range);
  const std::size_t end = range == last_range ? slots_by_first_pair_.size() : listed(range + 1);
  for (std::size_t k = begin; k < end; ++k) evaluate_walls_and_reset(slots_by_first_pair_[k]);
  // Without pairs: slot × ranges / count = range exactly for slots in [⌈range count / ranges⌉, …).
  const std::size_t count = particles_.size();
  const auto ranges = static_cast<std::size_t>(partition_.ranges());
  const auto first_slot = [&](std::size_t k) { return (k * count + ranges - 1) / ranges; };
  const auto from = std::lower_bound(slots_without_pairs_.begin(), slots_without_pairs_.end(), first_slot(range));
  const auto to = std::lower_bound(from, slots_without_pairs_.end(), first_slot(range + 1));
  for (auto slot = from; slot != to; ++slot) evaluate_walls_and_reset(*slot);
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

// After the threaded pair loop, for the pairs first … last of a particle or a tally chunk (in list
// order): the first whose result the loop did not add in list order. That is `first` when they
// straddle a cut (no one thread added them all), else the steal point of their range; past
// `last` when the range's owner evaluated them all.
std::size_t Simulation::first_pair_not_added(std::size_t first, std::size_t last) const noexcept {
  const int range = range_of_pair(first);
  return range != range_of_pair(last) ? first : std::max(first, steal_point(range));
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
    const PairSolution solution = [&] {
      if (!(reach > 0.0)) return PairSolution{};
      const BodyRef body{p.semi_axes[slot], p.position[slot], p.orientation[slot], p.mean_radius[slot], shape};
      return solve_wall(body, WallPlane{wall.position, wall.side}, is_sphere_[slot] != 0, history, cache,
                        wall_context(slot));
    }();
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
  const double distance_sq = (centre_j - p.position[i]).squaredNorm();
  // Built in place by the path that applies: a default solution overwritten by the solver's was
  // built and then copied, ~150 bytes a pair (the sphere slab's step 5 % faster without).
  const PairSolution solution = [&] {
    if (!(distance_sq < reach * reach)) {
      PairSolution apart;
      apart.clearance = std::sqrt(distance_sq) - reach;  // bounding spheres apart
      return apart;
    }
    // shapes_ holds posed ellipsoids for non-spheres only (a sphere meeting an ellipsoid is
    // posed on demand by the adapter, and never takes the separating-axis shortcut).
    const BodyRef body_i{p.semi_axes[i], p.position[i], p.orientation[i], p.mean_radius[i],
                         is_sphere_[i] == 0 ? &shapes_[i] : nullptr};
    const BodyRef body_j{p.semi_axes[j], centre_j, p.orientation[j], p.mean_radius[j],
                         is_sphere_[j] == 0 ? &shapes_[j] : nullptr};
    return solve_pair(body_i, body_j, is_sphere_[i] != 0 && is_sphere_[j] != 0, history, cache, pair_context(i, j));
  }();
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
  // Filled in a local and stored once: stores into `result` before the call to the contact
  // model could not be dropped, since the model might read that memory.
  PairResult touching;
  touching.contact = true;
  touching.regime = solution.law.regime;
  if (solution.law.regime != Regime::separated) {  // else overlapping below δ_p: no force
    const PairForces forces =
        pair_forces(solution, p.position[i], BodyMotion{p.velocity[i], omega_world_[i], p.mass[i]}, centre_j,
                    BodyMotion{p.velocity[j], omega_world_[j], p.mass[j]}, pair_context(i, j), settings_.dt, history);
    touching.force_on_j = forces.contact.on_j;
    touching.torque_i = forces.torque_on_i;
    touching.torque_j = forces.torque_on_j;
    touching.damping_dissipation = forces.contact.damping_dissipation;
    touching.friction_dissipation = forces.contact.friction_dissipation;
  }
  result = touching;
  pair_reported_[index] = 1;
  // The operations of gather_pair_forces(), zeros included (they can turn -0 into +0).
  if (add_to_i) {
    p.force[i] -= touching.force_on_j;
    p.torque[i] += touching.torque_i;
  }
  if (add_to_j) {
    p.force[j] += touching.force_on_j;
    p.torque[j] += touching.torque_j;
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

}  // namespace ellc::engine
