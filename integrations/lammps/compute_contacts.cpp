#include "compute_contacts.hpp"

#include <string>

#include "pair_ellipsoid_bk.hpp"

namespace ellc_lammps {

using namespace LAMMPS_NS;

ComputeEllipsoidContacts::ComputeEllipsoidContacts(LAMMPS* instance, int narg, char** arg)
    : Compute(instance, narg, arg) {
  if (narg != 3)
    fail(error, FLERR, std::string("compute ") + kStyle + " takes no arguments (compute ID group " + kStyle + ")");
  local_flag = 1;
  scalar_flag = 1;
  extscalar = 1;
  size_local_rows = 0;
  size_local_cols = kColumns;
}

ComputeEllipsoidContacts::~ComputeEllipsoidContacts() { memory->destroy(array_local); }

void ComputeEllipsoidContacts::init() {
  pair_ = dynamic_cast<PairEllipsoidBK*>(force->pair_match(PairEllipsoidBK::kStyle, 1));
  if (pair_ == nullptr) fail(error, FLERR, std::string("compute ") + kStyle + ": requires pair_style ellipsoid/bk");
  pair_->keep_contacts();
}

void ComputeEllipsoidContacts::check_current() const {
  if (pair_->computed_at() != update->ntimestep)
    fail(error, FLERR,
         std::string("compute ") + kStyle + ": pair ellipsoid/bk has no forces of step " +
             std::to_string(update->ntimestep) + " (use it on the steps of a run, e.g. from dump local)");
}

// Without newton_pair a pair across ranks is evaluated on both: keep it where i has the lower ID.
bool ComputeEllipsoidContacts::counted(const ContactRecord& c) const {
  const int* mask = atom->mask;
  if (!(mask[c.i] & groupbit) || !(mask[c.j] & groupbit)) return false;
  return force->newton_pair != 0 || c.j < atom->nlocal || atom->tag[c.i] < atom->tag[c.j];
}

double ComputeEllipsoidContacts::compute_scalar() {
  invoked_scalar = update->ntimestep;
  check_current();
  double mine = 0.0;
  for (const ContactRecord& c : pair_->contacts()) mine += counted(c) ? 1.0 : 0.0;
  MPI_Allreduce(&mine, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  return scalar;
}

void ComputeEllipsoidContacts::compute_local() {
  invoked_local = update->ntimestep;
  check_current();
  const auto& contacts = pair_->contacts();
  const tagint* tag = atom->tag;
  int rows = 0;
  for (const ContactRecord& c : contacts) rows += counted(c) ? 1 : 0;
  if (rows > capacity_) {
    capacity_ = rows;
    memory->destroy(array_local);
    memory->create(array_local, capacity_, kColumns, "ellipsoid/bk/contacts:array_local");
  }
  size_local_rows = rows;
  int row = 0;
  for (const ContactRecord& c : contacts) {
    if (!counted(c)) continue;
    double* out = array_local[row++];
    const double values[kColumns] = {static_cast<double>(tag[c.i]),
                                     static_cast<double>(tag[c.j]),
                                     c.overlap,
                                     c.max_overlap,
                                     static_cast<double>(c.regime),
                                     c.size_ratio,
                                     c.normal_force,
                                     c.tangential_force,
                                     c.force_on_i.x(),
                                     c.force_on_i.y(),
                                     c.force_on_i.z(),
                                     c.point.x(),
                                     c.point.y(),
                                     c.point.z()};
    std::copy(values, values + kColumns, out);
  }
}

double ComputeEllipsoidContacts::memory_usage() {
  return static_cast<double>(capacity_) * kColumns * static_cast<double>(sizeof(double));
}

}  // namespace ellc_lammps
