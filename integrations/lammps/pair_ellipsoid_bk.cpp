#include "pair_ellipsoid_bk.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "ellc/contact/contact_size.hpp"
#include "ellc/contact/proven_apart.hpp"
#include "ellc/engine/rigid_body.hpp"
#include "fix_contact_history.hpp"

namespace ellc_lammps {

using namespace LAMMPS_NS;

namespace {
std::string style_prefix() { return std::string("pair ") + PairEllipsoidBK::kStyle + ": "; }

// The calibrated range of the transition fits: semi-axes 1:[0.5..2]:[0.5..2] around the middle one.
bool in_calibrated_range(std::array<double, 3> semi_axes) {
  std::sort(semi_axes.begin(), semi_axes.end());
  return semi_axes[0] >= 0.5 * semi_axes[1] && semi_axes[2] <= 2.0 * semi_axes[1];
}
}  // namespace

PairEllipsoidBK::PairEllipsoidBK(LAMMPS* instance) : Pair(instance) {
  single_enable = 1;
  single_extra = kSingleExtra;
  svector = new double[kSingleExtra];
  restartinfo = 1;
  comm_forward = kBodyValues;
  finitecutflag = 1;
}

PairEllipsoidBK::~PairEllipsoidBK() {
  if (copymode) return;
  delete[] svector;
  svector = nullptr;
  // The history fix and the shape compute belong to this style; remove them with it.
  if (modify->find_fix(kHistoryFixId) >= 0) modify->delete_fix(kHistoryFixId);
  if (modify->find_compute(kBodiesComputeId) >= 0) modify->delete_compute(kBodiesComputeId);
  if (modify->find_compute(kOrientationsComputeId) >= 0) modify->delete_compute(kOrientationsComputeId);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairEllipsoidBK::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  // LAMMPS's own check would stop with "All pair coeffs are not set" before this style could say
  // which types lack coefficients; setflag is therefore always 1, and given_ records pair_coeff.
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) setflag[i][j] = 1;
  const auto size = static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
  given_.assign(size, 0);
  type_coefficients_.assign(size, {});
  pair_contexts_.assign(size, {});
  type_radius_.assign(static_cast<std::size_t>(n + 1), 0.0);
}

void PairEllipsoidBK::settings(int narg, char** arg) {
  skip_proven_separated_ = true;
  for (int at = 0; at < narg; at += 2) {
    const std::string keyword = arg[at];
    if ((keyword != "hertz" && keyword != "skip_proven_separated") || at + 1 >= narg)
      fail(error, FLERR,
           style_prefix() + "unknown setting '" + keyword +
               "' (expected: hertz hale|exact, skip_proven_separated yes|no)");
    const std::string value = arg[at + 1];
    if (keyword == "skip_proven_separated") {
      if (value != "yes" && value != "no")
        fail(error, FLERR, style_prefix() + "skip_proven_separated must be yes or no, got '" + value + "'");
      skip_proven_separated_ = value == "yes";
    } else if (value == "hale") {
      hertz_mode_ = ellc::HertzMode::hale;
    } else if (value == "exact") {
      hertz_mode_ = ellc::HertzMode::exact;
    } else {
      fail(error, FLERR, style_prefix() + "hertz must be hale or exact, got '" + value + "'");
    }
  }
  // Allocated here so a missing pair_coeff is reported by init_one with the types it concerns.
  if (!allocated) allocate();
}

void PairEllipsoidBK::coeff(int narg, char** arg) {
  if (narg < 2) fail(error, FLERR, style_prefix() + "pair_coeff needs two atom types");
  if (!allocated) allocate();
  int ilo = 0, ihi = 0, jlo = 0, jhi = 0;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const ParsedCoefficients parsed = parse_coefficients(std::vector<std::string>(arg + 2, arg + narg));
  if (!parsed.error.empty())
    fail(error, FLERR, style_prefix() + "pair_coeff " + arg[0] + " " + arg[1] + ": " + parsed.error);
  int count = 0;
  for (int i = ilo; i <= ihi; ++i) {
    for (int j = std::max(jlo, i); j <= jhi; ++j) {
      type_coefficients_[type_index(i, j)] = parsed.coefficients;
      given_[type_index(i, j)] = 1;
      ++count;
    }
  }
  if (count == 0) fail(error, FLERR, style_prefix() + "pair_coeff " + arg[0] + " " + arg[1] + " sets no pair of types");
}

void PairEllipsoidBK::init_style() {
  if (!atom->ellipsoid_flag)
    fail(error, FLERR,
         style_prefix() + "requires atom_style ellipsoid (this run uses atom_style " + atom->atom_style + ")");
  if (!atom->rmass_flag || !atom->angmom_flag || !atom->torque_flag)
    fail(error, FLERR, style_prefix() + "requires per-atom mass, angular momentum and torque (atom_style ellipsoid)");
  if (atom->tag_enable == 0) fail(error, FLERR, style_prefix() + "requires atom IDs");
  comm->ghost_velocity = 1;  // relative velocities at contact points of ghost partners
  neighbor->request(this, instance_me);

  // Internal computes: shapes (diameters) and quaternions of owned atoms; quaternions alone.
  if (modify->find_compute(kBodiesComputeId) < 0)
    modify->add_compute(std::string(kBodiesComputeId) +
                        " all property/atom shapex shapey shapez quatw quati quatj quatk");
  if (modify->find_compute(kOrientationsComputeId) < 0)
    modify->add_compute(std::string(kOrientationsComputeId) + " all property/atom quatw quati quatj quatk");
  bodies_compute_ = modify->compute[modify->find_compute(kBodiesComputeId)];
  bodies_compute_->init();
  orientations_compute_ = modify->compute[modify->find_compute(kOrientationsComputeId)];
  orientations_compute_->init();
  shapes_for_build_ = -1;

  // History fix. On a restarted run, creating it here picks up its records from the restart file.
  if (modify->find_fix(kHistoryFixId) < 0)
    modify->add_fix(std::string(kHistoryFixId) + " all " + FixContactHistory::kStyle + " " +
                    std::to_string(kHistoryDoubles));
  history_ = dynamic_cast<FixContactHistory*>(modify->fix[modify->find_fix(kHistoryFixId)]);
  if (history_ == nullptr || history_->values_per_contact() != kHistoryDoubles)
    fail(error, FLERR, style_prefix() + "fix " + kHistoryFixId + " exists but is not this style's history");
  history_->attach(this);

  // Per-contact records cost time and memory on every step: keep them only for their readers.
  // compute pair/local (through single()) is found here; compute ellipsoid/bk/contacts asks in its
  // init(), which LAMMPS runs after this one.
  keep_contacts_ = false;
  for (int index = 0; index < modify->ncompute; ++index)
    if (utils::strmatch(modify->compute[index]->style, "^pair/local")) keep_contacts_ = true;

  check_shapes();
}

// Per-type cutoff radii, and the bad-input checks on shapes: point particles, calibrated range.
void PairEllipsoidBK::check_shapes() {
  gather_bodies(false, true);  // owned atoms only: ghost lists are rebuilt later, in the setup of the run
  const int ntypes = atom->ntypes;
  std::vector<double> radius(static_cast<std::size_t>(ntypes + 1), 0.0);
  tagint first_point = 0;
  int outside_range = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    const double* body = &bodies_[static_cast<std::size_t>(i) * kBodyValues];
    if (!(body[0] > 0.0 && body[1] > 0.0 && body[2] > 0.0)) {
      if (first_point == 0 || atom->tag[i] < first_point) first_point = atom->tag[i];
      continue;
    }
    auto& r = radius[static_cast<std::size_t>(atom->type[i])];
    r = std::max({r, body[0], body[1], body[2]});
    if (!in_calibrated_range({body[0], body[1], body[2]})) outside_range = 1;
  }
  // first_point: smallest ID of a point particle on any rank (0 = none).
  tagint local_key = first_point == 0 ? MAXTAGINT : first_point, global_key = 0;
  MPI_Allreduce(&local_key, &global_key, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (global_key != MAXTAGINT)
    fail(error, FLERR,
         style_prefix() + "atom " + std::to_string(global_key) +
             " has zero shape (a point particle); every atom needs three positive semi-axes "
             "(set type ... shape, or the ellipsoid section of the data file)");
  type_radius_.assign(static_cast<std::size_t>(ntypes + 1), 0.0);
  MPI_Allreduce(radius.data(), type_radius_.data(), ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
  int any_outside = 0;
  MPI_Allreduce(&outside_range, &any_outside, 1, MPI_INT, MPI_MAX, world);
  if (any_outside && !warned_aspect_ && comm->me == 0) {
    error->warning(FLERR, style_prefix() +
                              "some particles have aspect ratios outside 1:[0.5..2]:[0.5..2], the range the "
                              "transition fits (eq. 52-54) were calibrated for; the law still evaluates");
    warned_aspect_ = true;
  }
}

double PairEllipsoidBK::init_one(int i, int j) {
  ellc::InteractionContext resolved;
  const auto with_hertz = [this](TypeCoefficients coefficients) {
    coefficients.model.hertz = hertz_mode_;  // a pair_style setting
    return coefficients;
  };
  if (given_[type_index(i, j)]) {
    resolved = explicit_pair(with_hertz(type_coefficients_[type_index(i, j)]));
  } else if (given_[type_index(i, i)] && given_[type_index(j, j)]) {
    std::string problem;
    resolved = mixed_pair(with_hertz(type_coefficients_[type_index(i, i)]),
                          with_hertz(type_coefficients_[type_index(j, j)]), problem);
    if (!problem.empty())
      fail(error, FLERR, style_prefix() + "types " + std::to_string(i) + " and " + std::to_string(j) + ": " + problem);
  } else {
    fail(error, FLERR,
         style_prefix() + "no pair_coeff for atom types " + std::to_string(i) + " " + std::to_string(j) +
             " (give 'pair_coeff " + std::to_string(i) + " " + std::to_string(j) + " E nu Y ...', or lines for " +
             std::to_string(i) + " " + std::to_string(i) + " and " + std::to_string(j) + " " + std::to_string(j) +
             " to mix from)");
  }
  pair_contexts_[type_index(i, j)] = resolved;
  pair_contexts_[type_index(j, i)] = resolved;

  // Contact is possible only within the sum of the largest semi-axes. A type without atoms gets
  // the largest radius present, so atoms added later are not missed (checked in compute()).
  const double largest = *std::max_element(type_radius_.begin(), type_radius_.end());
  const auto radius = [&](int type) {
    const double r = type_radius_[static_cast<std::size_t>(type)];
    return r > 0.0 ? r : largest;
  };
  const double cut = radius(i) + radius(j);
  return cut > 0.0 ? cut : 1.0;
}

// Owned atoms from the computes, then (to_ghosts) ghost atoms by a forward communication of
// values [forward_first_value_, kBodyValues) per atom: 7 doubles with shapes, 4 without.
void PairEllipsoidBK::gather_bodies(bool to_ghosts, bool with_shapes) {
  const int nmax = atom->nmax;
  if (bodies_.size() < static_cast<std::size_t>(nmax) * kBodyValues) {
    bodies_.resize(static_cast<std::size_t>(nmax) * kBodyValues);
  }
  Compute* source = with_shapes ? bodies_compute_ : orientations_compute_;
  source->compute_peratom();
  source->invoked_peratom = update->ntimestep;
  double** values = source->array_atom;
  for (int i = 0; i < atom->nlocal; ++i) {
    double* body = &bodies_[static_cast<std::size_t>(i) * kBodyValues];
    const double* row = values[i];
    if (with_shapes) {
      for (int k = 0; k < kShapeValues; ++k) body[k] = 0.5 * row[k];  // diameters → semi-axes
      row += kShapeValues;
    }
    std::copy(row, row + (kBodyValues - kShapeValues), body + kShapeValues);
  }
  if (to_ghosts) {
    forward_first_value_ = with_shapes ? 0 : kShapeValues;
    comm->forward_comm_pair(this);
  }
}

int PairEllipsoidBK::pack_forward_comm(int n, int* send_list, double* buffer, int /*pbc_flag*/, int* /*pbc*/) {
  const int width = kBodyValues - forward_first_value_;
  for (int k = 0; k < n; ++k) {
    const double* body = &bodies_[static_cast<std::size_t>(send_list[k]) * kBodyValues];
    std::copy(body + forward_first_value_, body + kBodyValues, buffer + static_cast<std::ptrdiff_t>(k) * width);
  }
  return n * width;
}

void PairEllipsoidBK::unpack_forward_comm(int n, int first, double* buffer) {
  const int width = kBodyValues - forward_first_value_;
  for (int k = 0; k < n; ++k) {
    const double* from = buffer + static_cast<std::ptrdiff_t>(k) * width;
    std::copy(from, from + width,
              bodies_.begin() + static_cast<std::ptrdiff_t>(first + k) * kBodyValues + forward_first_value_);
  }
}

namespace {
// Asks for the cache lines of [begin, begin + bytes) ahead of their use (a hint; never faults).
void prefetch(const void* begin, std::size_t bytes) {
  constexpr std::size_t kLine = 64;
  const auto* first = static_cast<const char*>(begin);
  for (std::size_t at = 0; at < bytes; at += kLine) __builtin_prefetch(first + at);
}
}  // namespace

// The posed ellipsoid, r̂ and motion of one atom (owned or ghost) for this step.
void PairEllipsoidBK::pose_atom(int index) {
  PosedAtom& posed = atoms_[static_cast<std::size_t>(index)];
  BodyState& motion = posed.motion;
  const double* body = &bodies_[static_cast<std::size_t>(index) * kBodyValues];
  const double* x = atom->x[index];
  const double* v = atom->v[index];
  motion.position = {x[0], x[1], x[2]};
  motion.velocity = {v[0], v[1], v[2]};
  motion.semi_axes = {body[0], body[1], body[2]};
  motion.orientation = Eigen::Quaterniond(body[3], body[4], body[5], body[6]);
  motion.mass = atom->rmass[index];
  motion.angular_velocity.setZero();
  if (motion.semi_axes.maxCoeff() > 0.0)
    motion.angular_velocity = ellc::engine::angular_velocity_from_momentum(
        {atom->angmom[index][0], atom->angmom[index][1], atom->angmom[index][2]}, motion.orientation,
        ellc::engine::solid_ellipsoid_inertia(motion.mass, motion.semi_axes));
  // Built in place (Ellipsoid is trivially destructible): no copy of its 300-odd bytes.
  std::construct_at(&posed.body, motion.semi_axes, ellc::Pose{motion.position, motion.orientation});
  if (motion.semi_axes != last_semi_axes_) {
    last_semi_axes_ = motion.semi_axes;
    last_mean_radius_ = posed.body.mean_radius();
  }
  posed.mean_radius = last_mean_radius_;
  posed.tag = atom->tag[index];
  posed.type = atom->type[index];
  posed_[static_cast<std::size_t>(index)] = 1;
}

void PairEllipsoidBK::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  if (!history_->slots_match_neighbor_list())
    fail_one(error, FLERR, style_prefix() + "contact history is out of step with the neighbor list (internal error)");
  // Shapes after every list build (new ghosts, reordered atoms) and in the setup of each run
  // (a shape may have been set since); quaternions every step.
  const bool with_shapes = update->setupflag != 0 || neighbor->ncalls != shapes_for_build_;
  gather_bodies(true, with_shapes);
  if (with_shapes) shapes_for_build_ = neighbor->ncalls;
  // Proven-apart pairs (the built-in engine's skip_proven_separated): a pair found apart with a
  // clearance along its stored separating axis stays apart while its two bodies' points move less
  // than that in total, and evaluating it again would change nothing (PairSolution::clearance).
  // Travel and these budgets restart with every list build (new slots) and every run's setup
  // (atoms may have been moved between runs).
  const bool restart_travel = with_shapes;
  if (restart_travel) history_->clear_slot_budgets();

  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const tagint* tag = atom->tag;
  const int* type = atom->type;
  double** x = atom->x;
  double** f = atom->f;
  double** torque = atom->torque;
  const bool newton = force->newton_pair != 0;
  const double timestep = update->dt;
  // The setup of a run recomputes the forces of the current step, whose contacts were already
  // advanced by the last step of the previous run (or are fresh): the history must not move again.
  const bool during_setup = update->setupflag != 0;
  const bool skip_apart = skip_proven_separated_ && !during_setup;
  const int history_size = kHistoryDoubles;
  std::array<double, kHistoryDoubles> scratch{};

  // Per atom, owned and ghost, once per step: the bounding sphere and the size check. Owned atoms
  // are posed now (the wall fix reads them too); a ghost only when one of its pairs needs it, as
  // many ghosts of the cutoff shell touch nothing.
  if (atoms_.size() < static_cast<std::size_t>(nall)) atoms_.resize(static_cast<std::size_t>(nall));
  posed_.assign(static_cast<std::size_t>(nall), 0);
  spheres_.resize(static_cast<std::size_t>(nall));
  travel_.resize(static_cast<std::size_t>(nall));
  last_pose_.resize(static_cast<std::size_t>(nall) * kPoseValues);
  for (int index = 0; index < nall; ++index) {
    const double* body = &bodies_[static_cast<std::size_t>(index) * kBodyValues];
    const double largest = std::max({body[0], body[1], body[2]});
    const double type_radius = type_radius_[static_cast<std::size_t>(type[index])];
    if (largest > type_radius && type_radius > 0.0)
      fail_one(error, FLERR,
               style_prefix() + "atom " + std::to_string(tag[index]) +
                   " is larger than any atom of its type was at the start of the run; re-run to update "
                   "the contact cutoffs");
    // Read once into locals: stores through `last` could otherwise alias x and the quaternion.
    const double centre[3] = {x[index][0], x[index][1], x[index][2]};
    const double quaternion[4] = {body[kShapeValues], body[kShapeValues + 1], body[kShapeValues + 2],
                                  body[kShapeValues + 3]};
    spheres_[static_cast<std::size_t>(index)] = {centre[0], centre[1], centre[2], largest};
    // No point of the body moved more than its centre plus the chord of the rotation at the
    // bounding radius: 2 sin(θ/2) R ≤ 2 |q − q_last| R for unit quaternions (|q − q_last| ≥ √2
    // when their dot product is negative, and 2√2 R exceeds any rotation's chord). The factors and
    // the last term cover rounding and the quaternions' normalisation (|q| = 1 to rounding).
    double* last = &last_pose_[static_cast<std::size_t>(index) * kPoseValues];
    double& travel = travel_[static_cast<std::size_t>(index)];
    if (restart_travel) {
      travel = 0.0;
    } else {
      const double dx = centre[0] - last[0], dy = centre[1] - last[1], dz = centre[2] - last[2];
      const double dw = quaternion[0] - last[3], di = quaternion[1] - last[4], dj = quaternion[2] - last[5],
                   dk = quaternion[3] - last[6];
      travel += ellc::bounded_displacement(std::sqrt(dx * dx + dy * dy + dz * dz)) +
                std::sqrt(dw * dw + di * di + dj * dj + dk * dk) * (2.0 * (1.0 + 1e-9)) * largest + 1e-12 * largest;
    }
    std::copy(centre, centre + 3, last);
    std::copy(quaternion, quaternion + 4, last + 3);
  }
  for (int index = 0; index < nlocal; ++index) pose_atom(index);

  long touching = 0;
  long proven_apart = 0;
  contacts_.clear();
  const bool keep_contacts = keep_contacts_;
  const NeighList* neighbors = list;
  for (int ii = 0; ii < neighbors->inum; ++ii) {
    const int i = neighbors->ilist[ii];
    const int* jlist = neighbors->firstneigh[i];
    const int count = neighbors->numneigh[i];
    const BoundingSphere sphere_i = spheres_[static_cast<std::size_t>(i)];

    // Broad test on the bounding spheres. The pairs that pass have their data fetched now, so it
    // arrives while the test runs on and the pairs before them are solved (a pair's atom and
    // history are otherwise cache misses: the time of a memory access is that of much arithmetic).
    // Two atoms ahead: its neighbor list; one atom ahead: the bounding spheres that list names
    // (fetched one round earlier), so the broad test below finds them in cache.
    if (ii + 2 < neighbors->inum) prefetch(neighbors->firstneigh[neighbors->ilist[ii + 2]], 64);
    if (ii + 1 < neighbors->inum) {
      const int next = neighbors->ilist[ii + 1];
      const int* next_list = neighbors->firstneigh[next];
      for (int jj = 0; jj < std::min(neighbors->numneigh[next], 16); ++jj)
        __builtin_prefetch(&spheres_[static_cast<std::size_t>(next_list[jj] & NEIGHMASK)]);
    }
    candidates_.clear();
    constexpr int kAhead = 4;
    for (int jj = 0; jj < count; ++jj) {
      if (jj + kAhead < count) __builtin_prefetch(&spheres_[static_cast<std::size_t>(jlist[jj + kAhead] & NEIGHMASK)]);
      const int j = jlist[jj] & NEIGHMASK;
      const BoundingSphere& sphere_j = spheres_[static_cast<std::size_t>(j)];
      const double reach = sphere_i.radius + sphere_j.radius;
      const double dx = sphere_i.x - sphere_j.x, dy = sphere_i.y - sphere_j.y, dz = sphere_i.z - sphere_j.z;
      if (dx * dx + dy * dy + dz * dz >= reach * reach) {  // bounding spheres apart
        if (!during_setup && history_->slot_active(i, jj)) {
          double* history = history_->slot_values(i, jj);
          std::fill(history, history + kHistoryDoubles, 0.0);
          history_->set_slot_active(i, jj, false);
          history_->set_slot_budget(i, jj, 0.0);  // the proof needs the separating axis just dropped
        }
        continue;
      }
      if (skip_apart &&
          travel_[static_cast<std::size_t>(i)] + travel_[static_cast<std::size_t>(j)] < history_->slot_budget(i, jj)) {
        ++proven_apart;  // still apart along the stored axis: solve_pair's shortcut would say so
        continue;
      }
      if (posed_[static_cast<std::size_t>(j)] == 0) pose_atom(j);
      prefetch(&atoms_[static_cast<std::size_t>(j)], sizeof(PosedAtom));
      prefetch(history_->slot_values(i, jj), kHistoryDoubles * sizeof(double));
      prefetch(f[j], 3 * sizeof(double));
      prefetch(torque[j], 3 * sizeof(double));
      candidates_.emplace_back(jj, j);
    }

    for (const auto& [jj, j] : candidates_) {
      double* history = history_->slot_values(i, jj);
      if (during_setup) {  // evaluate on a copy: the stored history is already that of this step
        std::copy(history, history + history_size, scratch.begin());
        history = scratch.data();
      }
      // Canonical orientation: a = lower atom ID.
      const PosedAtom& atom_i = atoms_[static_cast<std::size_t>(i)];
      const PosedAtom& atom_j = atoms_[static_cast<std::size_t>(j)];
      const bool i_is_a = atom_i.tag < atom_j.tag;
      const int a = i_is_a ? i : j;
      const int b = i_is_a ? j : i;
      const PosedAtom& atom_a = atoms_[static_cast<std::size_t>(a)];
      const PosedAtom& atom_b = atoms_[static_cast<std::size_t>(b)];
      const PairEvaluation result = evaluate_pair(
          {atom_a.body, atom_a.mean_radius, atom_a.motion}, {atom_b.body, atom_b.mean_radius, atom_b.motion},
          pair_contexts_[type_index(atom_i.type, atom_j.type)], timestep, history, pair_scratch_);
      if (result.geometry_failed && narrow_phase_failures_++ == 0)
        error->warning(FLERR, style_prefix() + "the narrow phase did not converge for atoms " + std::to_string(tag[a]) +
                                  " and " + std::to_string(tag[b]) + " at step " + std::to_string(update->ntimestep) +
                                  "; the pair is treated as not touching (reported once per rank)");
      if (!during_setup) {
        history_->set_slot_active(i, jj, result.touching || result.keep_warm_start);
        const double reach =
            spheres_[static_cast<std::size_t>(i)].radius + spheres_[static_cast<std::size_t>(j)].radius;
        const double usable = result.keep_warm_start ? ellc::usable_clearance(result.clearance, reach) : 0.0;
        history_->set_slot_budget(
            i, jj,
            usable > 0.0 ? travel_[static_cast<std::size_t>(i)] + travel_[static_cast<std::size_t>(j)] + usable : 0.0);
      }
      if (!result.touching) continue;
      ++touching;

      const Eigen::Vector3d force_on_i = i_is_a ? Eigen::Vector3d(-result.force_on_b) : result.force_on_b;
      if (keep_contacts) {
        ContactRecord& record = contacts_.emplace_back();
        record.i = i;
        record.j = j;
        record.overlap = result.overlap;
        record.max_overlap = result.law.max_overlap;
        record.regime = static_cast<int>(result.law.regime);
        ellc::ContactConstants size;  // the one constant c_c/r̂ needs, into the engine's definition
        size.contact_radius_sq_per_overlap = result.contact_radius_sq_per_overlap;
        record.size_ratio =
            ellc::contact_size_ratio(size, result.law.max_overlap, std::min(atom_a.mean_radius, atom_b.mean_radius));
        record.normal_force = result.normal_force;
        record.tangential_force = (result.force_on_b - result.normal_force * result.normal).norm();
        record.force_on_i = force_on_i;
        record.point = result.point;
      }
      const Eigen::Vector3d& torque_on_i = i_is_a ? result.torque_on_a : result.torque_on_b;
      const Eigen::Vector3d& torque_on_j = i_is_a ? result.torque_on_b : result.torque_on_a;
      for (int k = 0; k < 3; ++k) {
        f[i][k] += force_on_i[k];
        torque[i][k] += torque_on_i[k];
      }
      if (newton || j < nlocal) {
        for (int k = 0; k < 3; ++k) {
          f[j][k] -= force_on_i[k];
          torque[j][k] += torque_on_j[k];
        }
      }
      if (evflag) {
        const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
        ev_tally_xyz(i, j, nlocal, newton ? 1 : 0, 0.0, 0.0, force_on_i.x(), force_on_i.y(), force_on_i.z(), dx, dy,
                     dz);
      }
    }
  }
  touching_pairs_ = touching;
  pairs_proven_apart_ = proven_apart;
  computed_at_ = update->ntimestep;
  if (vflag_fdotr) virial_fdotr_compute();
}

double PairEllipsoidBK::single(int i, int j, int /*itype*/, int /*jtype*/, double rsq, double /*factor_coul*/,
                               double /*factor_lj*/, double& fforce) {
  fforce = 0.0;
  std::fill(svector, svector + kSingleExtra, 0.0);
  if (computed_at_ != update->ntimestep) return 0.0;  // no forces of this step (yet)
  if (contact_index_at_ != computed_at_) {
    contact_index_.clear();
    const auto nall = static_cast<std::uint64_t>(atom->nlocal + atom->nghost);
    for (std::size_t k = 0; k < contacts_.size(); ++k)
      contact_index_[static_cast<std::uint64_t>(contacts_[k].i) * nall + static_cast<std::uint64_t>(contacts_[k].j)] =
          k;
    contact_index_at_ = computed_at_;
  }
  const auto nall = static_cast<std::uint64_t>(atom->nlocal + atom->nghost);
  double sign = 1.0;  // the record's i is this call's i (+1) or its j (−1)
  auto found = contact_index_.find(static_cast<std::uint64_t>(i) * nall + static_cast<std::uint64_t>(j));
  if (found == contact_index_.end()) {
    found = contact_index_.find(static_cast<std::uint64_t>(j) * nall + static_cast<std::uint64_t>(i));
    sign = -1.0;
  }
  if (found == contact_index_.end()) return 0.0;
  const ContactRecord& record = contacts_[found->second];
  const Eigen::Vector3d force_on_i = sign * record.force_on_i;
  const double* x_i = atom->x[i];
  const double* x_j = atom->x[j];
  const Eigen::Vector3d apart(x_i[0] - x_j[0], x_i[1] - x_j[1], x_i[2] - x_j[2]);
  if (rsq > 0.0) fforce = force_on_i.dot(apart) / rsq;  // F·d̂ / r: LAMMPS's convention, F = fforce d for central forces
  const double values[kSingleExtra] = {record.overlap,    record.max_overlap,  double(record.regime),
                                       record.size_ratio, record.normal_force, record.tangential_force,
                                       force_on_i.x(),    force_on_i.y(),      force_on_i.z(),
                                       record.point.x(),  record.point.y(),    record.point.z()};
  std::copy(values, values + kSingleExtra, svector);
  return 0.0;
}

// Restart files carry the settings and every explicit pair_coeff line; mixing is redone on read.
void PairEllipsoidBK::write_restart_settings(FILE* file) {
  // Bit 0: hertz exact; bit 1: skip_proven_separated no (so files of earlier builds read as yes).
  const int mode = (hertz_mode_ == ellc::HertzMode::exact ? 1 : 0) | (skip_proven_separated_ ? 0 : 2);
  std::fwrite(&mode, sizeof(int), 1, file);
}

void PairEllipsoidBK::read_restart_settings(FILE* file) {
  int mode = 0;
  if (comm->me == 0) utils::sfread(FLERR, &mode, sizeof(int), 1, file, nullptr, error);
  MPI_Bcast(&mode, 1, MPI_INT, 0, world);
  hertz_mode_ = (mode & 1) != 0 ? ellc::HertzMode::exact : ellc::HertzMode::hale;
  skip_proven_separated_ = (mode & 2) == 0;
}

void PairEllipsoidBK::write_restart(FILE* file) {
  write_restart_settings(file);
  for (int i = 1; i <= atom->ntypes; ++i) {
    for (int j = i; j <= atom->ntypes; ++j) {
      const int given = given_[type_index(i, j)];
      std::fwrite(&given, sizeof(int), 1, file);
      if (!given) continue;
      const auto values = type_coefficients_[type_index(i, j)].serialize();
      std::fwrite(values.data(), sizeof(double), values.size(), file);
    }
  }
}

void PairEllipsoidBK::read_restart(FILE* file) {
  read_restart_settings(file);
  allocate();
  for (int i = 1; i <= atom->ntypes; ++i) {
    for (int j = i; j <= atom->ntypes; ++j) {
      int given = 0;
      if (comm->me == 0) utils::sfread(FLERR, &given, sizeof(int), 1, file, nullptr, error);
      MPI_Bcast(&given, 1, MPI_INT, 0, world);
      given_[type_index(i, j)] = static_cast<char>(given);
      if (!given) continue;
      std::array<double, TypeCoefficients::kSerializedSize> values{};
      if (comm->me == 0) utils::sfread(FLERR, values.data(), sizeof(double), values.size(), file, nullptr, error);
      MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, world);
      type_coefficients_[type_index(i, j)] = TypeCoefficients::deserialize(values);
    }
  }
}

double PairEllipsoidBK::memory_usage() {
  return static_cast<double>(bodies_.capacity() * sizeof(double) + atoms_.capacity() * sizeof(PosedAtom) +
                             spheres_.capacity() * sizeof(BoundingSphere) +
                             (travel_.capacity() + last_pose_.capacity()) * sizeof(double) +
                             contacts_.capacity() * sizeof(ContactRecord));
}

}  // namespace ellc_lammps
