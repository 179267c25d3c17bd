#pragma once
// pair_style ellipsoid/bk: the Becker–Kamlah elastoplastic normal contact between ellipsoids
// (atom_style ellipsoid), with normal damping and tangential Coulomb friction with history.
//
//   pair_style ellipsoid/bk [hertz hale|exact]
//   pair_coeff I J E nu Y [keyword value ...]          (see pair_coefficients.hpp, docs/lammps.md)
//
// Shapes and quaternions of owned atoms come from an internal compute property/atom; the pair
// style forwards them to ghost atoms itself. Contact history lives in fix ellipsoid/bk/history,
// which this style creates. Time integration: fix nve/asphere (it integrates the torques).

#include <cstdio>
#include <string>
#include <vector>

#include "ellc/geometry/ellipsoid.hpp"
#include "lammps_includes.hpp"
#include "pair_adapter.hpp"
#include "pair_coefficients.hpp"

namespace ellc_lammps {

class FixContactHistory;

class PairEllipsoidBK : public LAMMPS_NS::Pair {
 public:
  static constexpr const char* kStyle = "ellipsoid/bk";
  static constexpr const char* kHistoryFixId = "ELLC_BK_HISTORY";
  static constexpr const char* kBodiesComputeId = "ELLC_BK_BODIES";

  explicit PairEllipsoidBK(LAMMPS_NS::LAMMPS* lmp);
  ~PairEllipsoidBK() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  void write_restart(FILE* file) override;
  void read_restart(FILE* file) override;
  void write_restart_settings(FILE* file) override;
  void read_restart_settings(FILE* file) override;
  int pack_forward_comm(int n, int* list, double* buffer, int pbc_flag, int* pbc) override;
  void unpack_forward_comm(int n, int first, double* buffer) override;
  double memory_usage() override;

  // Pairs in contact (δ > 0) on this rank at the last force evaluation (diagnostics, benchmark).
  [[nodiscard]] long touching_pairs() const { return touching_pairs_; }

 private:
  static constexpr int kBodyValues = 7;  // semi-axes (3), quaternion w i j k (4)

  void allocate();
  [[nodiscard]] std::size_t type_index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(atom->ntypes + 1) + static_cast<std::size_t>(j);
  }
  void gather_bodies(bool to_ghosts);
  void check_shapes();
  [[nodiscard]] BodyState body_state(int index) const;

  ellc::HertzMode hertz_mode_ = ellc::HertzMode::hale;
  std::vector<char> given_;                              // 1 where pair_coeff I J was given, (ntypes+1)²
  std::vector<TypeCoefficients> type_coefficients_;      // as given by pair_coeff, (ntypes+1)²
  std::vector<ellc::InteractionContext> pair_contexts_;  // resolved (explicit or mixed) by init_one
  std::vector<double> type_radius_;                      // largest semi-axis of any atom of the type
  FixContactHistory* history_ = nullptr;
  LAMMPS_NS::Compute* bodies_compute_ = nullptr;
  std::vector<double> bodies_;           // per atom, owned + ghost: kBodyValues
  std::vector<ellc::Ellipsoid> shapes_;  // per atom, owned + ghost, rebuilt every step
  std::vector<BodyState> motions_;       // velocity, angular velocity, mass (same indexing)
  std::vector<double> mean_radii_;       // r̂ = (abc)^{1/3}
  bool warned_aspect_ = false;
  long narrow_phase_failures_ = 0;
  long touching_pairs_ = 0;
};

}  // namespace ellc_lammps
