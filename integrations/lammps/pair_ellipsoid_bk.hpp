#pragma once
// pair_style ellipsoid/bk: the Becker–Kamlah elastoplastic normal contact between ellipsoids
// (atom_style ellipsoid), with normal damping and tangential Coulomb friction with history.
//
//   pair_style ellipsoid/bk [hertz hale|exact] [skip_proven_separated yes|no]
//   pair_coeff I J E nu Y [keyword value ...]          (see pair_coefficients.hpp, docs/lammps.md)
//
// Shapes and quaternions of owned atoms come from internal computes property/atom; the pair
// style forwards them to ghost atoms itself: shapes only after the ghosts were rebuilt (they do
// not change within a run), quaternions every step. Contact history lives in fix ellipsoid/bk/history,
// which this style creates. Time integration: fix nve/asphere (it integrates the torques).

#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ellc/geometry/ellipsoid.hpp"
#include "lammps_includes.hpp"
#include "pair_adapter.hpp"
#include "pair_coefficients.hpp"

namespace ellc_lammps {

class FixContactHistory;

// One touching pair of the last force evaluation, for per-contact output (single(), compute
// ellipsoid/bk/contacts). Atom i is the neighbor list's first atom; vectors are in the world frame.
struct ContactRecord {
  int i = 0;  // local indices (j may be a ghost)
  int j = 0;
  double overlap = 0.0;      // δ
  double max_overlap = 0.0;  // δ_*
  int regime = 0;  // ellc::Regime as a number: 0 below δ_p, 1 elastic, 2 elastic-plastic, 3 fully plastic, 4 unloading
  double size_ratio = 0.0;  // c_c/r̂ (r̂ the smaller of the two), as the built-in engine's validity report
  double normal_force = 0.0;
  double tangential_force = 0.0;  // |F_t|
  Eigen::Vector3d force_on_i = Eigen::Vector3d::Zero();
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

class PairEllipsoidBK : public LAMMPS_NS::Pair {
 public:
  static constexpr const char* kStyle = "ellipsoid/bk";
  static constexpr const char* kHistoryFixId = "ELLC_BK_HISTORY";
  static constexpr const char* kBodiesComputeId = "ELLC_BK_BODIES";       // shapes and quaternions
  static constexpr const char* kOrientationsComputeId = "ELLC_BK_QUATS";  // quaternions only

  explicit PairEllipsoidBK(LAMMPS_NS::LAMMPS* lmp);
  ~PairEllipsoidBK() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  // The force of a touching pair (i, j) as the last compute() applied it: fforce·(x_i − x_j) is its
  // part along the centre line; the extra values (compute pair/local p1..p12) are δ, δ_*, regime,
  // c_c/r̂, F_n, |F_t|, the force on i (x y z) and the contact point (x y z). Zero for pairs not
  // touching. Energy 0: the law is dissipative (docs/lammps.md).
  double single(int i, int j, int itype, int jtype, double rsq, double factor_coul, double factor_lj,
                double& fforce) override;
  void write_restart(FILE* file) override;
  void read_restart(FILE* file) override;
  void write_restart_settings(FILE* file) override;
  void read_restart_settings(FILE* file) override;
  int pack_forward_comm(int n, int* list, double* buffer, int pbc_flag, int* pbc) override;
  void unpack_forward_comm(int n, int first, double* buffer) override;
  double memory_usage() override;

  // Pairs in contact (δ > 0) on this rank at the last force evaluation (diagnostics, benchmark).
  [[nodiscard]] long touching_pairs() const { return touching_pairs_; }
  // Pairs skipped at the last force evaluation because they were proven apart (see compute()).
  [[nodiscard]] long pairs_proven_apart() const { return pairs_proven_apart_; }

  // For fix wall/ellipsoid/bk: the bodies this step's compute() posed, owned and ghost atoms,
  // valid from compute() until the atoms move (computed_at() is that step).
  [[nodiscard]] LAMMPS_NS::bigint computed_at() const { return computed_at_; }
  [[nodiscard]] const ellc::Ellipsoid& posed_body(int index) const {
    return atoms_[static_cast<std::size_t>(index)].body;
  }
  [[nodiscard]] double mean_radius(int index) const { return atoms_[static_cast<std::size_t>(index)].mean_radius; }
  [[nodiscard]] const BodyState& motion(int index) const { return atoms_[static_cast<std::size_t>(index)].motion; }
  // pair_coeff I I as given (the material of type I), or null when that line is missing.
  [[nodiscard]] const TypeCoefficients* type_coefficients(int type) const {
    return given_[type_index(type, type)] ? &type_coefficients_[type_index(type, type)] : nullptr;
  }
  [[nodiscard]] ellc::HertzMode hertz_mode() const { return hertz_mode_; }
  // The touching pairs of the last compute() on this rank (computed_at()). Kept only when a reader
  // exists: compute pair/local (found by init_style) or a reader that asked (keep_contacts()).
  [[nodiscard]] const std::vector<ContactRecord>& contacts() const { return contacts_; }
  // Asks compute() to keep contacts() from the next force evaluation on (until the next init_style;
  // compute ellipsoid/bk/contacts calls it from its init(), which runs after the pair's).
  void keep_contacts() { keep_contacts_ = true; }
  [[nodiscard]] bool keeps_contacts() const { return keep_contacts_; }

 private:
  static constexpr int kBodyValues = 7;  // semi-axes (3), then quaternion w i j k (4)
  static constexpr int kShapeValues = 3;
  static constexpr int kPoseValues = 7;    // last_pose_: centre (3), quaternion (4)
  static constexpr int kSingleExtra = 12;  // semi-axes (3), quaternion w i j k (4)

  void allocate();
  [[nodiscard]] std::size_t type_index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(atom->ntypes + 1) + static_cast<std::size_t>(j);
  }
  // Shapes (with_shapes) and quaternions of owned atoms into bodies_, then (to_ghosts) to ghosts.
  void gather_bodies(bool to_ghosts, bool with_shapes);
  void check_shapes();

  ellc::HertzMode hertz_mode_ = ellc::HertzMode::hale;
  bool skip_proven_separated_ = true;                    // pair_style setting; `no` evaluates every candidate pair
  std::vector<char> given_;                              // 1 where pair_coeff I J was given, (ntypes+1)²
  std::vector<TypeCoefficients> type_coefficients_;      // as given by pair_coeff, (ntypes+1)²
  std::vector<ellc::InteractionContext> pair_contexts_;  // resolved (explicit or mixed) by init_one
  std::vector<double> type_radius_;                      // largest semi-axis of any atom of the type
  FixContactHistory* history_ = nullptr;
  LAMMPS_NS::Compute* bodies_compute_ = nullptr;
  LAMMPS_NS::Compute* orientations_compute_ = nullptr;
  // neighbor->ncalls when bodies_ last got every atom's shape: ghosts (and the order of owned
  // atoms) change only when lists are built, so until the next build quaternions suffice.
  LAMMPS_NS::bigint shapes_for_build_ = -1;
  int forward_first_value_ = 0;  // what pack/unpack_forward_comm move: values [first, kBodyValues)
  // Everything one atom contributes to its pairs, in one place so that a pair touches few cache
  // lines: the posed ellipsoid, its motion and r̂ = (abc)^{1/3}. Owned + ghost, rebuilt every step.
  struct PosedAtom {
    ellc::Ellipsoid body{Eigen::Vector3d::Ones()};
    BodyState motion;
    double mean_radius = 1.0;
    LAMMPS_NS::tagint tag = 0;  // copies of atom->tag and atom->type: read with the rest, no extra miss
    int type = 0;
  };
  void pose_atom(int index);
  // The broad test's data, 32 bytes per atom: centre and bounding radius (largest semi-axis).
  struct BoundingSphere {
    double x, y, z, radius;
  };
  std::vector<double> bodies_;    // per atom, owned + ghost: kBodyValues
  std::vector<PosedAtom> atoms_;  // owned atoms posed every step, ghosts when a pair first needs them
  std::vector<char> posed_;       // 1 where atoms_ holds this step's pose
  std::vector<BoundingSphere> spheres_;
  // Per atom, owned + ghost, since the last list build: how far any point of the body may have
  // moved (travel_), and its centre and quaternion at the last force evaluation (last_pose_).
  std::vector<double> travel_;
  std::vector<double> last_pose_;
  long pairs_proven_apart_ = 0;
  Eigen::Vector3d last_semi_axes_ = Eigen::Vector3d::Zero();  // r̂ of the last atom posed, reused for
  double last_mean_radius_ = 0.0;                             // equal semi-axes (one cube root less)
  std::vector<std::pair<int, int>> candidates_;               // (jj, j) of one atom i whose bounding spheres meet
  bool keep_contacts_ = false;
  ellc::ContactCache pair_scratch_;  // evaluate_pair's working space, reused by every pair
  bool warned_aspect_ = false;
  long narrow_phase_failures_ = 0;
  long touching_pairs_ = 0;
  LAMMPS_NS::bigint computed_at_ = -1;
  std::vector<ContactRecord> contacts_;
  std::unordered_map<std::uint64_t, std::size_t> contact_index_;  // (i, j) → contacts_, built by single()
  LAMMPS_NS::bigint contact_index_at_ = -1;
};

}  // namespace ellc_lammps
