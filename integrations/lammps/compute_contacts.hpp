#pragma once
// compute ellipsoid/bk/contacts: one row per touching pair of pair ellipsoid/bk at the last force
// evaluation (both atoms in the group), for dump local and compute reduce:
//
//   compute ID group-ID ellipsoid/bk/contacts
//
// Columns: 1 ID of atom i, 2 ID of atom j, 3 δ, 4 δ_*, 5 regime (0 overlapping below δ_p,
// 1 elastic, 2 elastic-plastic, 3 fully plastic, 4 unloading), 6 c_c/r̂, 7 F_n, 8 |F_t|,
// 9–11 force on i (x y z), 12–14 contact point (x y z). Each contact appears once over all ranks.
// Its global scalar is the number of those contacts over all ranks (2 × it / N is the built-in
// engine's coordination number: contacts that touch, δ > 0).

#include <vector>

#include "lammps_includes.hpp"

namespace ellc_lammps {

class PairEllipsoidBK;
struct ContactRecord;

class ComputeEllipsoidContacts : public LAMMPS_NS::Compute {
 public:
  static constexpr const char* kStyle = "ellipsoid/bk/contacts";
  static constexpr int kColumns = 14;

  ComputeEllipsoidContacts(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~ComputeEllipsoidContacts() override;
  void init() override;
  void compute_local() override;
  double compute_scalar() override;
  double memory_usage() override;

 private:
  PairEllipsoidBK* pair_ = nullptr;
  void check_current() const;
  [[nodiscard]] bool counted(const ContactRecord& contact) const;
  int capacity_ = 0;
};

}  // namespace ellc_lammps
