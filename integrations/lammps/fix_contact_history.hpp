#pragma once
// fix ellipsoid/bk/history: the per-contact state of pair ellipsoid/bk (δ_*, the tangential
// spring, the narrow-phase warm start), kept exact across time steps, MPI ranks, atom migration
// and restart files. Created by the pair style; users do not declare it.
//
// Two representations, as in any LAMMPS neighbor-history scheme:
//  * "slots", one per neighbor-list entry (i, jj), which the pair style reads and writes each step;
//  * "records", one list per atom of (partner tag, values), which travel with the atom.
// Slots → records happens before atoms move (pre_exchange, post_run, restart output); records →
// slots after a neighbor list is built (post_neighbor). Every contact is recorded at both of its
// atoms; with newton_pair on, records stored at ghost atoms are sent back to their owners by a
// reverse communication, so each owner knows all contacts of its atoms before migrating them.
//
// The values of one contact are stored in a canonical orientation (body I = the lower atom ID),
// so both copies are identical and no sign convention has to be applied when they swap sides.

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <vector>

#include "lammps_includes.hpp"

namespace ellc_lammps {

class FixContactHistory : public LAMMPS_NS::Fix {
 public:
  static constexpr const char* kStyle = "ellipsoid/bk/history";

  // fix ID group ellipsoid/bk/history nvalues
  FixContactHistory(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);
  ~FixContactHistory() override;

  int setmask() override;
  void init() override;
  void setup_post_neighbor() override;
  void pre_exchange() override;
  void min_pre_exchange() override;
  void post_neighbor() override;
  void min_post_neighbor() override;
  void post_run() override;
  void write_restart(FILE* file) override;
  void restart(char* /*buffer*/) override {}

  void grow_arrays(int nmax) override;
  void copy_arrays(int from, int to, int delflag) override;
  void set_arrays(int index) override;
  int pack_exchange(int index, double* buffer) override;
  int unpack_exchange(int index, double* buffer) override;
  int pack_restart(int index, double* buffer) override;
  void unpack_restart(int index, int nth) override;
  int size_restart(int index) override;
  int maxsize_restart() override;
  int pack_reverse_comm_size(int n, int first) override;
  int pack_reverse_comm(int n, int first, double* buffer) override;
  void unpack_reverse_comm(int n, int* list, double* buffer) override;
  double memory_usage() override;

  // --- interface for the pair style --------------------------------------------------------
  void attach(LAMMPS_NS::Pair* pair) { pair_ = pair; }
  [[nodiscard]] int values_per_contact() const { return nvalues_; }
  // True when the slots belong to the neighbor list built last (checked by the pair each step).
  [[nodiscard]] bool slots_match_neighbor_list() const;
  [[nodiscard]] double* slot_values(int i, int jj) {
    return slot_values_.data() + (slot_offset_[static_cast<std::size_t>(i)] + static_cast<std::size_t>(jj)) *
                                     static_cast<std::size_t>(nvalues_);
  }
  [[nodiscard]] bool slot_active(int i, int jj) const {
    return slot_active_[slot_offset_[static_cast<std::size_t>(i)] + static_cast<std::size_t>(jj)] != 0;
  }
  void set_slot_active(int i, int jj, bool active) {
    slot_active_[slot_offset_[static_cast<std::size_t>(i)] + static_cast<std::size_t>(jj)] = active ? 1 : 0;
  }
  // The pair style's proof that a slot's pair is apart (its "clearance budget", see
  // PairEllipsoidBK::compute): 0 when there is none. Zero for every slot of a new list.
  [[nodiscard]] double slot_budget(int i, int jj) const {
    return slot_budget_[slot_offset_[static_cast<std::size_t>(i)] + static_cast<std::size_t>(jj)];
  }
  void set_slot_budget(int i, int jj, double budget) {
    slot_budget_[slot_offset_[static_cast<std::size_t>(i)] + static_cast<std::size_t>(jj)] = budget;
  }
  void clear_slot_budgets() { std::fill(slot_budget_.begin(), slot_budget_.end(), 0.0); }
  // Slots holding a record on this rank: contacts, and near pairs that keep only the narrow
  // phase's separating axis (diagnostics).
  [[nodiscard]] long active_contacts() const;

 private:
  void slots_to_records();
  [[nodiscard]] std::size_t record_stride() const { return static_cast<std::size_t>(nvalues_) + 1; }
  [[nodiscard]] int record_count(int index) const {
    return static_cast<int>(records_[static_cast<std::size_t>(index)].size() / record_stride());
  }
  void append_record(int index, double partner_tag, const double* values);
  void update_max_exchange();

  LAMMPS_NS::Pair* pair_ = nullptr;
  int nvalues_ = 0;
  bool newton_pair_ = true;
  // Per atom (owned, and ghost while records are gathered): [tag, v_0 .. v_{n-1}] per partner.
  std::vector<std::vector<double>> records_;
  // Per neighbor-list entry: values and whether they are worth keeping (a contact, or a near
  // pair's separating axis).
  std::vector<std::size_t> slot_offset_;
  std::vector<double> slot_values_;
  std::vector<unsigned char> slot_active_;
  std::vector<double> slot_budget_;
  int nlocal_neigh_ = 0;
  int nall_neigh_ = 0;
  bool slots_valid_ = false;
  LAMMPS_NS::bigint slots_built_at_ = -1;  // neighbor->lastcall when the slots were built
};

}  // namespace ellc_lammps
