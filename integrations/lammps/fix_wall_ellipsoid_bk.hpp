#pragma once
// fix wall/ellipsoid/bk: two z planes that the ellipsoids of pair ellipsoid/bk touch through the
// shared contact model's wall path (src/ellc/contact/pair_contact.hpp: solve_wall, wall_forces),
// the counterpart of fix wall/gran for this pair style.
//
//   fix ID group wall/ellipsoid/bk zplane ZLO ZHI [keyword value ...]
//
//   ZLO, ZHI   NULL (no plane), a number, or v_name (an equal-style variable: the plane follows it,
//              its speed for damping and friction is the change over the last step / dt)
//   rigid | material E nu Y | material particle
//              what the planes are made of (required); Y may be inf (never yields); particle:
//              each atom's own material, the mirror-image half-space
//   contact-model keywords of pair_coeff (normal, damping_model, damping_ratio, normal_damping,
//              tangential_damping, tangential_model, tangential_stiffness, friction,
//              narrow_phase_final_step, damping): they override the model of the atom's
//              pair_coeff I I line, which the wall contact otherwise uses (law, sub-models, μ, ζ)
//   fix_modify ID servo lo|hi P RATE [servo_gain g servo_tolerance t] | servo off: switches the servo
//              between runs; the plane keeps its position and the atoms their history (a plane
//              released from the servo follows its ZLO/ZHI value again, e.g. a redefined variable)
//   servo lo|hi P RATE   that plane moves to hold the pressure P on it (force / (xprd·yprd)):
//              speed −RATE·clamp(gain (P − p)/P, −1, 1) towards the particles (the built-in
//              engine's servo); servo_gain g (default 5), servo_tolerance t (default 0: within
//              t·P of the target the plane stands still)
//
// Global vector of 9: the force the particles exert on the lower plane (fx fy fz), on the upper
// plane (fx fy fz), then the planes' positions zlo zhi, then the built-in engine's unbalanced-force
// ratio (ellc/engine/equilibrium.hpp: mean |net contact force| of the group's atoms over the mean
// |contact force| of the pair and wall contacts). Element 9 reads each atom's force right after
// this fix has added the wall forces, so it needs this fix before every other fix that adds forces
// (gravity, drag), and the pair's contact records (compute ellipsoid/bk/contacts defined). Per atom and plane, the
// contact history record (contact_history.hpp) travels with the atom and into restart files; redefine the fix with the
// same ID after read_restart to pick it up (the servo's position and speed come back too).

#include <array>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "ellc/contact/contact_model.hpp"
#include "ellc/material/material.hpp"
#include "lammps_includes.hpp"

namespace ellc_lammps {

class PairEllipsoidBK;

class FixWallEllipsoidBK : public LAMMPS_NS::Fix {
 public:
  static constexpr const char* kStyle = "wall/ellipsoid/bk";
  static constexpr int kPlanes = 2;

  FixWallEllipsoidBK(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixWallEllipsoidBK() override;

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  double compute_vector(int index) override;
  int modify_param(int narg, char** arg) override;

  void write_restart(FILE* file) override;
  void restart(char* buffer) override;
  void grow_arrays(int nmax) override;
  void copy_arrays(int from, int to, int delflag) override;
  void set_arrays(int index) override;
  int pack_exchange(int index, double* buffer) override;
  int unpack_exchange(int index, double* buffer) override;
  int pack_restart(int index, double* buffer) override;
  void unpack_restart(int index, int nth) override;
  int size_restart(int index) override;
  int maxsize_restart() override;
  double memory_usage() override;

 private:
  enum class PlaneKind { none, constant, variable };
  enum class WallMaterial { unset, rigid, given, particle };

  struct Plane {
    PlaneKind kind = PlaneKind::none;
    double value = 0.0;    // constant
    std::string variable;  // variable name (without v_)
    int variable_index = -1;
    bool servo = false;
    double position = 0.0;  // now
    double velocity = 0.0;  // along z, over the last step
    bool placed = false;    // position holds a value (set at the first setup or from a restart)
  };

  [[nodiscard]] std::string prefix() const;
  void parse_plane(int plane, const std::string& word);
  // servo lo|hi P RATE at words[at]: sets the servo, returns the words used (4).
  std::size_t parse_servo(const std::vector<std::string>& words, std::size_t at);
  [[nodiscard]] double plane_target(int plane);  // the value of a constant or variable plane
  void move_planes(bool during_setup);
  void check_between_planes();
  void wall_contacts(bool during_setup);
  void update_servo();
  void reduce_forces();
  void tally_balance();  // the sums of the unbalanced-force ratio, after the wall forces are added
  [[nodiscard]] double unbalanced_force_ratio();
  [[nodiscard]] double plane_pressure(int plane) const;  // on the plane, from the reduced force
  [[nodiscard]] double* history(int index, int plane) {
    return history_.data() + (static_cast<std::size_t>(index) * kPlanes + static_cast<std::size_t>(plane)) * kRecord;
  }

  static constexpr std::size_t kRecord = 9;  // ellc::ContactHistory::kDoubles, checked in the .cpp
  static constexpr int kAtomValues = kPlanes * static_cast<int>(kRecord);

  std::array<Plane, kPlanes> planes_;
  WallMaterial material_kind_ = WallMaterial::unset;
  ellc::Material wall_material_;
  std::vector<std::pair<std::string, std::string>> contact_keywords_;  // as given, replayed per type
  int servo_plane_ = -1;
  double servo_pressure_ = 0.0;
  double servo_rate_ = 0.0;
  double servo_gain_ = 5.0;
  double servo_tolerance_ = 0.0;

  PairEllipsoidBK* pair_ = nullptr;
  std::vector<ellc::InteractionContext> contexts_;  // per atom type (index 0 unused)
  std::vector<char> type_ready_;                    // 1 where pair_coeff I I exists
  std::vector<double> history_;                     // per atom: kPlanes records
  // fx, fy, fz on the lower plane, then the upper (the global vector's first 6), then Σ k_n of
  // each plane's contacts (the servo's loop gain, engine/servo.hpp): reduced together.
  std::array<double, 8> force_local_{};
  std::array<double, 8> force_all_{};
  bool force_reduced_ = false;
  // Σ |net contact force|, atoms, Σ |contact force|, contacts: this rank's, and over all ranks.
  std::array<double, 4> balance_local_{};
  std::array<double, 4> balance_all_{};
  bool balance_reduced_ = false;
  std::string earlier_force_fix_;  // a fix that adds forces before this one (element 9 unusable)
  long failures_ = 0;
  int* extlist_owned_ = nullptr;
};

}  // namespace ellc_lammps
