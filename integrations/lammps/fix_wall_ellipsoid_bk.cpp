#include "fix_wall_ellipsoid_bk.hpp"

#include <input.h>
#include <variable.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "ellc/contact/contact_history.hpp"
#include "ellc/contact/contact_parameters.hpp"
#include "ellc/contact/pair_contact.hpp"
#include "ellc/engine/equilibrium.hpp"
#include "ellc/engine/servo.hpp"
#include "pair_coefficients.hpp"
#include "pair_ellipsoid_bk.hpp"

namespace ellc_lammps {

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

static_assert(ellc::ContactHistory::kDoubles == 9, "kRecord in fix_wall_ellipsoid_bk.hpp");

namespace {
constexpr const char* kPlaneNames[2] = {"ZLO", "ZHI"};
constexpr int kSide[2] = {1, -1};  // the particles are above the lower plane, below the upper one
}  // namespace

std::string FixWallEllipsoidBK::prefix() const { return std::string("fix ") + kStyle + ": "; }

FixWallEllipsoidBK::FixWallEllipsoidBK(LAMMPS* instance, int narg, char** arg) : Fix(instance, narg, arg) {
  const std::vector<std::string> words(arg + 3, arg + narg);
  if (words.size() < 3 || words[0] != "zplane")
    fail(error, FLERR,
         prefix() + "expected 'zplane ZLO ZHI' after the style (fix ID group " + kStyle +
             " zplane ZLO ZHI rigid|material E nu Y|material particle [keyword value ...])");
  parse_plane(0, words[1]);
  parse_plane(1, words[2]);
  if (planes_[0].kind == PlaneKind::none && planes_[1].kind == PlaneKind::none)
    fail(error, FLERR, prefix() + "zplane: ZLO and ZHI are both NULL (expected at least one plane)");
  if (planes_[0].kind == PlaneKind::constant && planes_[1].kind == PlaneKind::constant &&
      !(planes_[0].value < planes_[1].value))
    fail(error, FLERR,
         prefix() + "zplane: ZLO = " + words[1] + " is not below ZHI = " + words[2] + " (expected ZLO < ZHI)");

  ellc::ContactModelBuilder check(ellc::ContactModel{});  // the keywords' values, checked once here
  for (std::size_t at = 3; at < words.size();) {
    const std::string& keyword = words[at];
    const auto number = [&](std::size_t k, const char* what) {
      if (at + k >= words.size()) fail(error, FLERR, prefix() + keyword + ": missing value " + what);
      const auto value = to_number(words[at + k]);
      if (!value) fail(error, FLERR, prefix() + keyword + ": " + what + " '" + words[at + k] + "' is not a number");
      return *value;
    };
    if (keyword == "rigid" || keyword == "material") {
      if (material_kind_ != WallMaterial::unset)
        fail(error, FLERR, prefix() + keyword + ": the wall material is given twice (rigid or material, once)");
      if (keyword == "rigid") {
        material_kind_ = WallMaterial::rigid;
        wall_material_ = ellc::rigid_material();
        at += 1;
      } else if (at + 1 < words.size() && words[at + 1] == "particle") {
        material_kind_ = WallMaterial::particle;
        at += 2;
      } else {
        material_kind_ = WallMaterial::given;
        wall_material_ = {number(1, "E"), number(2, "nu"), number(3, "Y")};
        // Y = inf: a plate that never yields; validated like a finite one otherwise.
        ellc::Material checked = wall_material_;
        if (std::isinf(checked.yield_stress) && checked.yield_stress > 0.0) checked.yield_stress = 1.0;
        if (std::string problem = ellc::validation_error(checked, "material"); !problem.empty())
          fail(error, FLERR, prefix() + problem);
        at += 4;
      }
      continue;
    }
    if (keyword == "servo") {
      at += parse_servo(words, at);
      continue;
    }
    if (keyword == "servo_gain" || keyword == "servo_tolerance") {
      const double value = number(1, "value");
      if (!(value >= 0.0 && std::isfinite(value)) || (keyword == "servo_gain" && value == 0.0))
        fail(error, FLERR,
             prefix() + keyword + " = " + words[at + 1] +
                 (keyword == "servo_gain" ? ": expected a finite number > 0" : ": expected a finite number >= 0"));
      (keyword == "servo_gain" ? servo_gain_ : servo_tolerance_) = value;
      at += 2;
      continue;
    }
    std::string problem;
    const int used = read_contact_keyword(words, at, check, problem);
    if (used < 0) fail(error, FLERR, prefix() + problem);
    if (used == 0)
      fail(error, FLERR,
           prefix() + "unknown keyword '" + keyword +
               "' (expected rigid, material, servo, servo_gain, servo_tolerance, " + contact_keyword_names() + ")");
    contact_keywords_.emplace_back(words[at], words[at + 1]);
    at += static_cast<std::size_t>(used);
  }
  if (material_kind_ == WallMaterial::unset)
    fail(error, FLERR,
         prefix() + "material: missing wall material (give rigid, material E nu Y, or material particle)");
  if ((servo_gain_ != 5.0 || servo_tolerance_ != 0.0) && servo_plane_ < 0)
    fail(error, FLERR, prefix() + "servo_gain and servo_tolerance need the servo keyword");

  vector_flag = 1;
  size_vector = 9;
  global_freq = 1;
  extvector = -1;
  extlist_owned_ = new int[9]{1, 1, 1, 1, 1, 1, 0, 0, 0};  // forces are extensive, positions and the ratio not
  extlist = extlist_owned_;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = kAtomValues;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixWallEllipsoidBK::~FixWallEllipsoidBK() {
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  extlist = nullptr;
  delete[] extlist_owned_;
}

std::size_t FixWallEllipsoidBK::parse_servo(const std::vector<std::string>& words, std::size_t at) {
  if (at + 1 >= words.size() || (words[at + 1] != "lo" && words[at + 1] != "hi"))
    fail(error, FLERR,
         prefix() + "servo: expected servo lo|hi PRESSURE RATE, got '" +
             (at + 1 < words.size() ? words[at + 1] : std::string("nothing")) + "' as the plane");
  const auto number = [&](std::size_t k, const char* what) {
    const auto value = at + k < words.size() ? to_number(words[at + k]) : std::nullopt;
    if (!(value && *value > 0.0 && std::isfinite(*value)))
      fail(error, FLERR,
           prefix() + "servo: " + what + " = '" + (at + k < words.size() ? words[at + k] : std::string()) +
               "': expected a finite number > 0");
    return *value;
  };
  const int plane = words[at + 1] == "lo" ? 0 : 1;
  const double pressure = number(2, "PRESSURE");
  const double rate = number(3, "RATE");
  if (planes_[static_cast<std::size_t>(plane)].kind == PlaneKind::none)
    fail(error, FLERR,
         prefix() + "servo " + words[at + 1] + ": that plane is NULL (give " + kPlaneNames[plane] +
             " a starting position)");
  for (Plane& p : planes_) p.servo = false;
  servo_plane_ = plane;
  servo_pressure_ = pressure;
  servo_rate_ = rate;
  planes_[static_cast<std::size_t>(plane)].servo = true;
  return 4;
}

int FixWallEllipsoidBK::modify_param(int narg, char** arg) {
  if (narg < 1 || std::string(arg[0]) != "servo") return 0;
  if (narg >= 2 && std::string(arg[1]) == "off") {
    for (Plane& p : planes_) p.servo = false;
    servo_plane_ = -1;
    return 2;
  }
  const std::vector<std::string> words(arg, arg + narg);
  std::size_t used = parse_servo(words, 0);
  while (used + 1 < words.size() && (words[used] == "servo_gain" || words[used] == "servo_tolerance")) {
    const auto value = to_number(words[used + 1]);
    if (!(value && *value >= 0.0 && std::isfinite(*value)))
      fail(error, FLERR, prefix() + words[used] + " = " + words[used + 1] + ": expected a finite number >= 0");
    (words[used] == "servo_gain" ? servo_gain_ : servo_tolerance_) = *value;
    used += 2;
  }
  return static_cast<int>(used);
}

void FixWallEllipsoidBK::parse_plane(int plane, const std::string& word) {
  Plane& p = planes_[static_cast<std::size_t>(plane)];
  if (word == "NULL") {
    p.kind = PlaneKind::none;
  } else if (word.rfind("v_", 0) == 0 && word.size() > 2) {
    p.kind = PlaneKind::variable;
    p.variable = word.substr(2);
  } else if (const auto value = to_number(word); value && std::isfinite(*value)) {
    p.kind = PlaneKind::constant;
    p.value = *value;
  } else {
    fail(error, FLERR,
         prefix() + "zplane: " + kPlaneNames[plane] + " = '" + word +
             "': expected NULL, a number or v_name (an equal-style variable)");
  }
}

int FixWallEllipsoidBK::setmask() { return POST_FORCE; }

void FixWallEllipsoidBK::init() {
  if (!atom->ellipsoid_flag)
    fail(error, FLERR, prefix() + "requires atom_style ellipsoid (this run uses atom_style " + atom->atom_style + ")");
  pair_ = dynamic_cast<PairEllipsoidBK*>(force->pair_match(PairEllipsoidBK::kStyle, 1));
  if (pair_ == nullptr)
    fail(error, FLERR,
         prefix() + "requires pair_style ellipsoid/bk (the wall contact takes each atom's shape and material from it)");
  for (Plane& p : planes_) {
    if (p.kind != PlaneKind::variable) continue;
    p.variable_index = input->variable->find(p.variable.c_str());
    if (p.variable_index < 0) fail(error, FLERR, prefix() + "zplane: variable '" + p.variable + "' does not exist");
    if (!input->variable->equalstyle(p.variable_index))
      fail(error, FLERR, prefix() + "zplane: variable '" + p.variable + "' is not equal-style");
  }

  // Element 9 reads f in post_force: only the pair's forces may be in it before this fix's.
  earlier_force_fix_.clear();
  for (int index = 0; index < modify->nfix && modify->fix[index] != this; ++index)
    if ((modify->fmask[index] & POST_FORCE) != 0 && earlier_force_fix_.empty())
      earlier_force_fix_ = modify->fix[index]->id;

  // The wall contact of each type: its pair_coeff I I model, overridden by this fix's keywords.
  const int ntypes = atom->ntypes;
  contexts_.assign(static_cast<std::size_t>(ntypes + 1), {});
  type_ready_.assign(static_cast<std::size_t>(ntypes + 1), 0);
  for (int type = 1; type <= ntypes; ++type) {
    const TypeCoefficients* coefficients = pair_->type_coefficients(type);
    if (coefficients == nullptr) continue;
    ellc::ContactModel start = coefficients->model;
    start.hertz = pair_->hertz_mode();
    ellc::ContactModelBuilder builder(start);
    for (const auto& [name, value] : contact_keywords_) {
      std::string problem;
      const std::vector<std::string> pair_words{name, value};
      if (read_contact_keyword(pair_words, 0, builder, problem) < 0) fail(error, FLERR, prefix() + problem);
    }
    ellc::ContactModel model = builder.finish();
    if (std::string problem = ellc::validation_error(model, "fix wall/ellipsoid/bk"); !problem.empty())
      fail(error, FLERR, prefix() + problem);
    const ellc::Material& particle = coefficients->material;
    const ellc::Material& wall = material_kind_ == WallMaterial::particle ? particle : wall_material_;
    contexts_[static_cast<std::size_t>(type)] = ellc::make_interaction(model, particle, wall);
    type_ready_[static_cast<std::size_t>(type)] = 1;
  }
  int missing = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if ((atom->mask[i] & groupbit) && !type_ready_[static_cast<std::size_t>(atom->type[i])])
      missing = std::max(missing, atom->type[i]);
  int missing_all = 0;
  MPI_Allreduce(&missing, &missing_all, 1, MPI_INT, MPI_MAX, world);
  if (missing_all > 0)
    fail(error, FLERR,
         prefix() + "atom type " + std::to_string(missing_all) + " has no pair_coeff " + std::to_string(missing_all) +
             " " + std::to_string(missing_all) + " (the wall contact takes the particles' material from it)");
}

double FixWallEllipsoidBK::plane_target(int plane) {
  Plane& p = planes_[static_cast<std::size_t>(plane)];
  if (p.kind == PlaneKind::variable) {
    modify->clearstep_compute();
    const double value = input->variable->compute_equal(p.variable_index);
    modify->addstep_compute(update->ntimestep + 1);
    if (!std::isfinite(value))
      fail(error, FLERR,
           prefix() + "zplane: variable '" + p.variable + "' gives " + std::to_string(value) + " for " +
               kPlaneNames[plane] + " at step " + std::to_string(update->ntimestep) + " (expected a finite number)");
    return value;
  }
  return p.value;
}

// Planes to this step: a variable is evaluated, a servo plane advances at the speed its pressure
// asked for last step. At a setup the planes stay (placed) or are placed for the first time.
void FixWallEllipsoidBK::move_planes(bool during_setup) {
  for (int w = 0; w < kPlanes; ++w) {
    Plane& p = planes_[static_cast<std::size_t>(w)];
    if (p.kind == PlaneKind::none) continue;
    if (!p.placed) {
      p.position = plane_target(w);
      p.velocity = 0.0;
      p.placed = true;
      continue;
    }
    if (during_setup) continue;
    if (p.servo) {
      p.position += update->dt * p.velocity;
    } else if (p.kind == PlaneKind::variable) {
      const double position = plane_target(w);
      p.velocity = (position - p.position) / update->dt;
      p.position = position;
    }
  }
  if (planes_[0].kind != PlaneKind::none && planes_[1].kind != PlaneKind::none &&
      !(planes_[0].position < planes_[1].position))
    fail(error, FLERR,
         prefix() + "zplane: ZLO = " + std::to_string(planes_[0].position) +
             " is not below ZHI = " + std::to_string(planes_[1].position) + " at step " +
             std::to_string(update->ntimestep) + " (expected ZLO < ZHI)");
}

// Every particle must start between the planes: a centre behind a plane has no wall contact the
// model can describe.
void FixWallEllipsoidBK::check_between_planes() {
  tagint worst[2] = {MAXTAGINT, MAXTAGINT};
  double where[2] = {0.0, 0.0};
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int w = 0; w < kPlanes; ++w) {
      const Plane& p = planes_[static_cast<std::size_t>(w)];
      if (p.kind == PlaneKind::none) continue;
      if (kSide[w] * (atom->x[i][2] - p.position) > 0.0) continue;
      if (atom->tag[i] < worst[w]) {
        worst[w] = atom->tag[i];
        where[w] = atom->x[i][2];
      }
    }
  }
  for (int w = 0; w < kPlanes; ++w) {
    tagint first = MAXTAGINT;
    MPI_Allreduce(&worst[w], &first, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (first == MAXTAGINT) continue;
    double z = first == worst[w] ? where[w] : -std::numeric_limits<double>::infinity();
    double z_all = 0.0;
    MPI_Allreduce(&z, &z_all, 1, MPI_DOUBLE, MPI_MAX, world);
    fail(error, FLERR,
         prefix() + "zplane: " + kPlaneNames[w] + " = " +
             std::to_string(planes_[static_cast<std::size_t>(w)].position) + (w == 0 ? " is above" : " is below") +
             " the centre of atom " + std::to_string(first) + " (z = " + std::to_string(z_all) +
             "); every particle of the group must start between the planes");
  }
}

void FixWallEllipsoidBK::setup(int /*vflag*/) {
  if (pair_->computed_at() != update->ntimestep)
    fail(error, FLERR, prefix() + "pair ellipsoid/bk did not compute this step (is it the pair style of this run?)");
  move_planes(true);
  check_between_planes();
  wall_contacts(true);
  tally_balance();
  reduce_forces();
  update_servo();
}

void FixWallEllipsoidBK::post_force(int /*vflag*/) {
  if (pair_->computed_at() != update->ntimestep)
    fail_one(error, FLERR, prefix() + "pair ellipsoid/bk did not compute this step (internal error)");
  move_planes(false);
  wall_contacts(false);
  tally_balance();
  if (servo_plane_ >= 0) {
    reduce_forces();
    update_servo();
  }
}

// Every owned atom of the group against each plane: solve_wall and wall_forces of the shared
// contact model, on the history record stored for that atom and plane.
void FixWallEllipsoidBK::wall_contacts(bool during_setup) {
  force_local_.fill(0.0);
  force_reduced_ = false;
  balance_local_.fill(0.0);
  balance_reduced_ = false;
  double** f = atom->f;
  double** torque = atom->torque;
  const int* mask = atom->mask;
  const int* type = atom->type;
  const double dt = update->dt;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const BodyState& motion = pair_->motion(i);
    const Eigen::Vector3d& semi_axes = motion.semi_axes;
    const double bounding = semi_axes.maxCoeff();
    const bool sphere = semi_axes.x() == semi_axes.y() && semi_axes.y() == semi_axes.z();
    const ellc::InteractionContext& context = contexts_[static_cast<std::size_t>(type[i])];
    for (int w = 0; w < kPlanes; ++w) {
      const Plane& p = planes_[static_cast<std::size_t>(w)];
      if (p.kind == PlaneKind::none) continue;
      double* stored = history(i, w);
      ellc::ContactHistory record = ellc::ContactHistory::read_from(stored);
      const double reach = bounding - kSide[w] * (motion.position.z() - p.position);
      if (reach <= 0.0 && !record.active()) continue;  // far from this plane, no contact to end
      ellc::ContactCache cache;  // constants rebuilt every step, as in the pair style; solution points into it
      // Built by the path that applies, as the engine's walls are (no default solution overwritten).
      const ellc::PairSolution solution = [&] {
        if (!(reach > 0.0)) return ellc::PairSolution{};
        const ellc::BodyRef body{semi_axes, motion.position, motion.orientation, pair_->mean_radius(i),
                                 &pair_->posed_body(i)};
        return ellc::solve_wall(body, ellc::WallPlane{p.position, kSide[w]}, sphere, record, cache, context);
      }();
      if (solution.status == ellc::PairStatus::failed) {
        if (failures_++ == 0)
          error->warning(FLERR, prefix() + "the wall contact of atom " + std::to_string(atom->tag[i]) +
                                    " could not be resolved; treated as not touching (reported once per rank)");
        continue;
      }
      if (solution.status == ellc::PairStatus::separated) {
        if (!during_setup) ellc::ContactHistory{}.write_to(stored);  // the contact ends (docs/model.md §5)
        continue;
      }
      balance_local_[3] += 1.0;                              // a contact, with or without force
      if (solution.law.regime != ellc::Regime::separated) {  // below δ_p: overlapping, no force
        const ellc::WallForces forces =
            ellc::wall_forces(solution, motion.position, {motion.velocity, motion.angular_velocity, motion.mass},
                              p.velocity, context, dt, record);
        for (int k = 0; k < 3; ++k) {
          f[i][k] -= forces.contact.on_j[k];
          torque[i][k] -= forces.lever_cross_force[k];
          force_local_[static_cast<std::size_t>(3 * w + k)] += forces.contact.on_j[k];
        }
        force_local_[static_cast<std::size_t>(6 + w)] += forces.contact.normal_stiffness;
        balance_local_[2] += forces.contact.on_j.norm();
      }
      if (!during_setup) record.write_to(stored);
    }
  }
}

// The atoms' net contact forces (pair + wall: no other fix has added to f yet, see init()) and
// the pair contacts, each once over all ranks (as compute ellipsoid/bk/contacts counts them).
void FixWallEllipsoidBK::tally_balance() {
  double** f = atom->f;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    balance_local_[0] += std::sqrt(f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2]);
    balance_local_[1] += 1.0;
  }
  if (!pair_->keeps_contacts()) return;
  for (const ContactRecord& c : pair_->contacts()) {
    if (force->newton_pair == 0 && c.j >= atom->nlocal && atom->tag[c.i] > atom->tag[c.j]) continue;
    balance_local_[2] += c.force_on_i.norm();
    balance_local_[3] += 1.0;
  }
}

double FixWallEllipsoidBK::unbalanced_force_ratio() {
  if (!earlier_force_fix_.empty())
    fail(error, FLERR,
         prefix() + "vector element 9 (the unbalanced-force ratio) needs this fix defined before fix " +
             earlier_force_fix_ + ", which adds forces first (define the wall fix before gravity and drag)");
  if (!pair_->keeps_contacts())
    fail(error, FLERR,
         prefix() +
             "vector element 9 (the unbalanced-force ratio) needs the pair's contact forces: define "
             "compute ID all ellipsoid/bk/contacts");
  if (!balance_reduced_) {
    MPI_Allreduce(balance_local_.data(), balance_all_.data(), 4, MPI_DOUBLE, MPI_SUM, world);
    balance_reduced_ = true;
  }
  return ellc::engine::unbalanced_force_ratio(balance_all_[0], static_cast<std::size_t>(balance_all_[1]),
                                              balance_all_[2], static_cast<std::size_t>(balance_all_[3]));
}

void FixWallEllipsoidBK::reduce_forces() {
  if (force_reduced_) return;
  MPI_Allreduce(force_local_.data(), force_all_.data(), static_cast<int>(force_local_.size()), MPI_DOUBLE, MPI_SUM,
                world);
  force_reduced_ = true;
}

double FixWallEllipsoidBK::plane_pressure(int plane) const {
  const double area = domain->xprd * domain->yprd;
  return plane == 0 ? -force_all_[2] / area : force_all_[5] / area;
}

// The built-in engine's servo (ellc/engine/servo.hpp): speed RATE·clamp(g (P − p)/P, −1, 1)
// towards the particles, capped at the stiffness of the plane's contacts.
void FixWallEllipsoidBK::update_servo() {
  if (servo_plane_ < 0) return;
  const ellc::engine::PlateServo servo{servo_pressure_, servo_pressure_, servo_rate_, servo_gain_, servo_tolerance_};
  const double stiffness_per_area =
      force_all_[static_cast<std::size_t>(6 + servo_plane_)] / (domain->xprd * domain->yprd);
  const double speed = ellc::engine::servo_speed(servo, plane_pressure(servo_plane_), stiffness_per_area, update->dt);
  planes_[static_cast<std::size_t>(servo_plane_)].velocity = kSide[servo_plane_] * speed;
}

double FixWallEllipsoidBK::compute_vector(int index) {
  if (index == 8) return unbalanced_force_ratio();
  if (index >= 6) {
    const Plane& p = planes_[static_cast<std::size_t>(index - 6)];
    return p.kind == PlaneKind::none ? 0.0 : p.position;
  }
  reduce_forces();
  return force_all_[static_cast<std::size_t>(index)];
}

// Global restart data: position, speed and placed flag of both planes.
void FixWallEllipsoidBK::write_restart(FILE* file) {
  if (comm->me != 0) return;
  double values[3 * kPlanes];
  for (int w = 0; w < kPlanes; ++w) {
    const Plane& p = planes_[static_cast<std::size_t>(w)];
    values[3 * w] = p.position;
    values[3 * w + 1] = p.velocity;
    values[3 * w + 2] = p.placed ? 1.0 : 0.0;
  }
  const int size = static_cast<int>(sizeof(values));
  std::fwrite(&size, sizeof(int), 1, file);
  std::fwrite(values, sizeof(values), 1, file);
}

void FixWallEllipsoidBK::restart(char* buffer) {
  double values[3 * kPlanes];
  std::memcpy(values, buffer, sizeof(values));
  for (int w = 0; w < kPlanes; ++w) {
    Plane& p = planes_[static_cast<std::size_t>(w)];
    if (p.kind == PlaneKind::none) continue;
    p.position = values[3 * w];
    p.velocity = values[3 * w + 1];
    p.placed = values[3 * w + 2] != 0.0;
  }
}

void FixWallEllipsoidBK::grow_arrays(int nmax) {
  history_.resize(static_cast<std::size_t>(nmax) * static_cast<std::size_t>(kAtomValues), 0.0);
}

void FixWallEllipsoidBK::copy_arrays(int from, int to, int /*delflag*/) {
  std::memcpy(history(to, 0), history(from, 0), kAtomValues * sizeof(double));
}

void FixWallEllipsoidBK::set_arrays(int index) { std::fill_n(history(index, 0), kAtomValues, 0.0); }

int FixWallEllipsoidBK::pack_exchange(int index, double* buffer) {
  std::memcpy(buffer, history(index, 0), kAtomValues * sizeof(double));
  return kAtomValues;
}

int FixWallEllipsoidBK::unpack_exchange(int index, double* buffer) {
  std::memcpy(history(index, 0), buffer, kAtomValues * sizeof(double));
  return kAtomValues;
}

// Restart buffers start with their own length, as LAMMPS expects of every fix.
int FixWallEllipsoidBK::pack_restart(int index, double* buffer) {
  buffer[0] = kAtomValues + 1;
  return pack_exchange(index, buffer + 1) + 1;
}

void FixWallEllipsoidBK::unpack_restart(int index, int nth) {
  double* extra = atom->extra[index];
  int at = 0;
  for (int skip = 0; skip < nth; ++skip) at += static_cast<int>(extra[at]);
  unpack_exchange(index, extra + at + 1);
}

int FixWallEllipsoidBK::size_restart(int /*index*/) { return kAtomValues + 1; }
int FixWallEllipsoidBK::maxsize_restart() { return kAtomValues + 1; }

double FixWallEllipsoidBK::memory_usage() { return static_cast<double>(history_.capacity() * sizeof(double)); }

}  // namespace ellc_lammps
