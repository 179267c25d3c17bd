#include "fix_contact_history.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace ellc_lammps {

using namespace LAMMPS_NS;
using namespace LAMMPS_NS::FixConst;

FixContactHistory::FixContactHistory(LAMMPS* instance, int narg, char** arg) : Fix(instance, narg, arg) {
  if (narg != 4)
    fail(error, FLERR,
         std::string("fix ") + kStyle +
             " takes one argument (values per contact); it is created by "
             "pair_style ellipsoid/bk and is not meant to be declared by hand");
  nvalues_ = utils::inumeric(FLERR, arg[3], false, instance);
  if (nvalues_ < 1) fail(error, FLERR, std::string("fix ") + kStyle + ": values per contact must be positive");

  restart_global = 1;   // only as a hook: write_restart() syncs the records on all ranks
  restart_peratom = 1;  // the records go into restart files
  create_attribute = 1;
  maxexchange_dynamic = 1;
  newton_pair_ = force->newton_pair != 0;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixContactHistory::~FixContactHistory() {
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixContactHistory::setmask() {
  return PRE_EXCHANGE | MIN_PRE_EXCHANGE | POST_NEIGHBOR | MIN_POST_NEIGHBOR | POST_RUN;
}

void FixContactHistory::init() {
  if (atom->tag_enable == 0) fail(error, FLERR, std::string("fix ") + kStyle + " needs atom IDs");
  if (pair_ == nullptr) fail(error, FLERR, std::string("fix ") + kStyle + " is not attached to pair ellipsoid/bk");
  if ((force->newton_pair != 0) != newton_pair_)
    fail(error, FLERR, std::string("fix ") + kStyle + ": the newton_pair setting changed after the fix was created");
  // Atoms must carry their records when some other fix migrates them in its own pre_exchange.
  for (int index = 0; index < modify->nfix; ++index) {
    if (modify->fix[index] == this) break;
    if (modify->fix[index]->pre_exchange_migrate)
      fail(error, FLERR,
           std::string("fix ") + kStyle + " must come before fix " + modify->fix[index]->id +
               ", which migrates atoms in pre_exchange");
  }
}

bool FixContactHistory::slots_match_neighbor_list() const {
  return slots_valid_ && slots_built_at_ == neighbor->lastcall;
}

long FixContactHistory::active_contacts() const {
  return static_cast<long>(std::count(slot_active_.begin(), slot_active_.end(), static_cast<unsigned char>(1)));
}

void FixContactHistory::append_record(int index, double partner_tag, const double* values) {
  std::vector<double>& list = records_[static_cast<std::size_t>(index)];
  list.push_back(partner_tag);
  list.insert(list.end(), values, values + nvalues_);
}

void FixContactHistory::update_max_exchange() {
  int most = 0;
  for (int index = 0; index < atom->nlocal; ++index) most = std::max(most, record_count(index));
  maxexchange = static_cast<int>(record_stride()) * most + 1;
}

// Slots → records. Collective when newton_pair is on (reverse communication).
void FixContactHistory::slots_to_records() {
  if (!slots_valid_ || pair_ == nullptr || pair_->list == nullptr) return;
  // Until the exchange that follows, local indices are those of the last neighbor list build.
  for (int index = 0; index < nall_neigh_; ++index) records_[static_cast<std::size_t>(index)].clear();
  const tagint* tag = atom->tag;
  const NeighList* list = pair_->list;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int* neighbors = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      if (!slot_active(i, jj)) continue;
      const int j = neighbors[jj] & NEIGHMASK;
      const double* values = slot_values(i, jj);
      append_record(i, static_cast<double>(tag[j]), values);
      // Without newton_pair, a ghost partner's owner evaluates the pair itself and keeps its copy.
      if (newton_pair_ || j < nlocal_neigh_) append_record(j, static_cast<double>(tag[i]), values);
    }
  }
  if (newton_pair_) comm->reverse_comm_fix_variable(this);
  for (int index = nlocal_neigh_; index < atom->nlocal; ++index) records_[static_cast<std::size_t>(index)].clear();
  update_max_exchange();
}

void FixContactHistory::pre_exchange() { slots_to_records(); }
void FixContactHistory::min_pre_exchange() { slots_to_records(); }
void FixContactHistory::post_run() { slots_to_records(); }

void FixContactHistory::write_restart(FILE* file) {
  // Called on every rank by write_restart/restart output, before the per-atom data is packed.
  // During a run the slots hold the truth; between runs post_run() has already synced them, and
  // atoms may have been reordered since, so the slots must not be used then.
  if (update->whichflag != 0) slots_to_records();
  if (comm->me == 0) {
    const int size = 0;
    std::fwrite(&size, sizeof(int), 1, file);
  }
}

// Records → slots, for the neighbor list that was just built.
void FixContactHistory::post_neighbor() {
  if (pair_ == nullptr || pair_->list == nullptr) return;
  nlocal_neigh_ = atom->nlocal;
  nall_neigh_ = atom->nlocal + atom->nghost;
  const tagint* tag = atom->tag;
  const NeighList* list = pair_->list;
  const auto stride = record_stride();
  const auto width = static_cast<std::size_t>(nvalues_);

  slot_offset_.assign(static_cast<std::size_t>(nall_neigh_) + 1, 0);
  std::size_t total = 0;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    slot_offset_[static_cast<std::size_t>(i)] = total;
    total += static_cast<std::size_t>(list->numneigh[i]);
  }
  slot_values_.assign(total * width, 0.0);
  slot_active_.assign(total, 0);
  slot_budget_.assign(total, 0.0);

  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const std::vector<double>& mine = records_[static_cast<std::size_t>(i)];
    if (mine.empty()) continue;
    const int* neighbors = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const auto partner = static_cast<double>(tag[neighbors[jj] & NEIGHMASK]);
      for (std::size_t at = 0; at < mine.size(); at += stride) {
        if (mine[at] != partner) continue;
        std::memcpy(slot_values(i, jj), &mine[at + 1], width * sizeof(double));
        set_slot_active(i, jj, true);
        break;
      }
    }
  }
  slots_valid_ = true;
  slots_built_at_ = neighbor->lastcall;
}

void FixContactHistory::setup_post_neighbor() { post_neighbor(); }
void FixContactHistory::min_post_neighbor() { post_neighbor(); }

void FixContactHistory::grow_arrays(int nmax) {
  if (static_cast<std::size_t>(nmax) > records_.size()) records_.resize(static_cast<std::size_t>(nmax));
}

void FixContactHistory::copy_arrays(int from, int to, int /*delflag*/) {
  records_[static_cast<std::size_t>(to)] = records_[static_cast<std::size_t>(from)];
}

void FixContactHistory::set_arrays(int index) { records_[static_cast<std::size_t>(index)].clear(); }

// Exchange and restart buffers: [count, (tag, values) × count].
int FixContactHistory::pack_exchange(int index, double* buffer) {
  const std::vector<double>& mine = records_[static_cast<std::size_t>(index)];
  buffer[0] = record_count(index);
  std::copy(mine.begin(), mine.end(), buffer + 1);
  return static_cast<int>(mine.size()) + 1;
}

int FixContactHistory::unpack_exchange(int index, double* buffer) {
  const auto size = static_cast<std::size_t>(buffer[0]) * record_stride();
  records_[static_cast<std::size_t>(index)].assign(buffer + 1, buffer + 1 + size);
  maxexchange = std::max(maxexchange, static_cast<int>(size) + 1);
  return static_cast<int>(size) + 1;
}

// Restart buffers start with their own length, as LAMMPS expects of every fix.
int FixContactHistory::pack_restart(int index, double* buffer) {
  const int size = pack_exchange(index, buffer + 1) + 1;
  buffer[0] = size;
  return size;
}

void FixContactHistory::unpack_restart(int index, int nth) {
  double* extra = atom->extra[index];
  int at = 0;
  for (int skip = 0; skip < nth; ++skip) at += static_cast<int>(extra[at]);
  unpack_exchange(index, extra + at + 1);
}

int FixContactHistory::size_restart(int index) {
  return static_cast<int>(records_[static_cast<std::size_t>(index)].size()) + 2;
}

int FixContactHistory::maxsize_restart() {
  int most = 0;
  for (int index = 0; index < atom->nlocal; ++index) most = std::max(most, size_restart(index));
  int most_all = 0;
  MPI_Allreduce(&most, &most_all, 1, MPI_INT, MPI_MAX, world);
  return most_all;
}

// Reverse communication: records gathered at ghost atoms go to their owners.
int FixContactHistory::pack_reverse_comm_size(int n, int first) {
  int size = 0;
  for (int index = first; index < first + n; ++index)
    size += 1 + static_cast<int>(records_[static_cast<std::size_t>(index)].size());
  return size;
}

int FixContactHistory::pack_reverse_comm(int n, int first, double* buffer) {
  int at = 0;
  for (int index = first; index < first + n; ++index) at += pack_exchange(index, buffer + at);
  return at;
}

void FixContactHistory::unpack_reverse_comm(int n, int* list, double* buffer) {
  int at = 0;
  for (int k = 0; k < n; ++k) {
    const auto size = static_cast<std::size_t>(buffer[at]) * record_stride();
    std::vector<double>& owner = records_[static_cast<std::size_t>(list[k])];
    owner.insert(owner.end(), buffer + at + 1, buffer + at + 1 + size);
    at += static_cast<int>(size) + 1;
  }
}

double FixContactHistory::memory_usage() {
  double bytes = static_cast<double>(records_.size() * sizeof(std::vector<double>));
  for (const auto& list : records_) bytes += static_cast<double>(list.capacity() * sizeof(double));
  bytes += static_cast<double>(slot_offset_.capacity() * sizeof(std::size_t));
  bytes += static_cast<double>(slot_values_.capacity() * sizeof(double));
  bytes += static_cast<double>(slot_active_.capacity());
  bytes += static_cast<double>(slot_budget_.capacity() * sizeof(double));
  return bytes;
}

}  // namespace ellc_lammps
