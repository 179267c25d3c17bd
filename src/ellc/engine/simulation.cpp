#include "ellc/engine/simulation.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "ellc/assert.hpp"
#include "ellc/contact/contact_energy.hpp"
#include "ellc/contact/proven_apart.hpp"
#include "ellc/engine/broad_phase.hpp"
#include "ellc/engine/cpu_load.hpp"
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
  // The wall owners' lists (compute_forces_threaded): the slots with pairs bucketed by their first
  // pair (a counting sort over pair indices; it reads pair_span_ only, not the large pair slots).
  std::vector<std::uint32_t> position(pairs_.size() + 1, 0);
  slots_without_pairs_.clear();
  for (std::size_t slot = 0; slot < count; ++slot) {
    if (pair_span_[slot].first <= pair_span_[slot].last)
      ++position[pair_span_[slot].first + 1];
    else
      slots_without_pairs_.push_back(static_cast<std::uint32_t>(slot));
  }
  for (std::size_t index = 0; index < pairs_.size(); ++index) position[index + 1] += position[index];
  slots_by_first_pair_.resize(count - slots_without_pairs_.size());
  first_pair_of_listed_.resize(slots_by_first_pair_.size());
  for (std::size_t slot = 0; slot < count; ++slot) {
    const PairSpan span = pair_span_[slot];
    if (span.first > span.last) continue;
    const std::uint32_t at = position[span.first]++;
    slots_by_first_pair_[at] = static_cast<std::uint32_t>(slot);
    first_pair_of_listed_[at] = span.first;
  }
  ELLC_ASSERT(slots_by_first_pair_.size() + slots_without_pairs_.size() == count,
              "every particle is listed once for its walls");
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
  const int threads = parallel() ? threads_ : 1;
  find_candidate_pairs(particles_, settings_.box, skin_, threads, spare_pairs_);
  released_work_ += carry_over_history(pairs_, spare_pairs_, threads);
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
// and all of them the CPU quota leaves worth running (thread_count.hpp) fed with the previous
// step's wall time and with whether other processes and the quota leave room for more than one
// thread (cpu_load.hpp: the process's reading, renewed every 50 ms; the first simulation of a
// process starts it in its constructor, and one built later has it before its first step).
void Simulation::choose_threads() noexcept {
  if (!settings_.adaptive_threads) {
    threads_ = omp_get_max_threads();
    return;
  }
  const std::optional<double> quota = process_cpu_quota();
  const int most = threads_within_quota(omp_get_max_threads(), quota);
  if (most != thread_choice_.most()) thread_choice_.reset(most);
  if (most > 1) {
    if (const auto reading = process_other_load(0.05)) {
      const double cores = std::min(static_cast<double>(reading->cores), quota.value_or(reading->cores));
      thread_choice_.set_room_for_more(room_for_more_than_one(reading->others_busy, cores));
    }
  }
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
