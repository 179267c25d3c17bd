#pragma once
// A packing from a file instead of the generator (`[packing] file = "..."`): users bring their
// own beds (CT reconstructions, drying simulations, other codes, a LAMMPS run). Two formats:
//
//  * a LAMMPS data file of atom_style ellipsoid (what `ellc export-lammps` writes): the header's
//    atom count and x/y box bounds, `Atoms # ellipsoid` lines `id type ellipsoidflag density x y z
//    [ix iy iz]` and `Ellipsoids` lines `id shapex shapey shapez quatw quati quatj quatk` (shapes
//    are diameters). Other sections (Masses, Velocities) are skipped; the density, types and
//    velocities of the file are not used: masses follow from the scenario's density, particles
//    start at rest. Lengths are µm, as the scenario's.
//  * a CSV file (a name ending in .csv) with a header naming the columns x, y, z, a, b, c (semi-
//    axes), qw, qx, qy, qz (unit quaternion, body → world), in any order; `id` is allowed and
//    ignored. Blank lines and lines starting with # are skipped.
//
// Particles get ids 0..N−1 in the file's order (data files: by atom ID). x and y are wrapped into
// the periodic box [0, lx) × [0, ly) (a data file's box must have the scenario's size); every
// particle must lie above the floor, z − (largest semi-axis) ≥ 0. Bad input throws InputError
// naming the file, the line and the field.

#include <string>
#include <vector>

#include "ellc/engine/particles.hpp"
#include "ellc/engine/settings.hpp"

namespace ellc::scenario {

// density: ng/µm³, after mass scaling (PackingSpec::density).
[[nodiscard]] engine::ParticleSet import_packing(const std::string& path, double density, const engine::Box& box);
// Several species ([[species]]): a data file's atom type t is species t − 1, of density
// species_densities[t − 1]; a type outside 1..S is refused with its line. One density: as above.
[[nodiscard]] engine::ParticleSet import_packing(const std::string& path, const std::vector<double>& species_densities,
                                                 const engine::Box& box);

}  // namespace ellc::scenario
