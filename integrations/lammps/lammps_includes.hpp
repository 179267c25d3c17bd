#pragma once
// The one place this integration includes LAMMPS headers: the fmt shim must come first (see
// fmt_compat.hpp). Only headers that Debian's liblammps-dev ships are used.

#include "fmt_compat.hpp"

// clang-format off
#include <atom.h>
#include <comm.h>
#include <compute.h>
#include <domain.h>
#include <error.h>
#include <fix.h>
#include <force.h>
#include <lammps.h>
#include <memory.h>
#include <modify.h>
#include <neigh_list.h>
#include <neighbor.h>
#include <output.h>
#include <pair.h>
#include <update.h>
#include <utils.h>
// clang-format on

#include <string>

namespace ellc_lammps {

// error->all with a std::string: the non-template overload, whose signature carries no fmt type.
[[noreturn]] inline void fail(LAMMPS_NS::Error* error, const char* file, int line, const std::string& message) {
  error->all(file, line, message);
}

// error->one: for conditions found on one rank only (error->all would wait for the others).
[[noreturn]] inline void fail_one(LAMMPS_NS::Error* error, const char* file, int line, const std::string& message) {
  error->one(file, line, message);
}

}  // namespace ellc_lammps
