#pragma once
// One in-process LAMMPS instance on MPI_COMM_WORLD, quiet (no log, no screen, no citation notice)
// and with ellc's styles registered: for the benchmark and the C++ tests that drive LAMMPS
// directly rather than through lmp_ellc.

#include <string>
#include <vector>

#include "lammps_includes.hpp"
#include "register_styles.hpp"

#include <input.h>

namespace ellc_lammps {

struct LammpsSession {
  LAMMPS_NS::LAMMPS* lmp = nullptr;

  LammpsSession() {
    std::vector<std::string> words{"ellc", "-log", "none", "-screen", "none", "-nocite"};
    std::vector<char*> argv;
    for (auto& word : words) argv.push_back(word.data());
    lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(argv.size()), argv.data(), MPI_COMM_WORLD);
    register_styles(lmp, built_against_version());
  }
  ~LammpsSession() { delete lmp; }
  LammpsSession(const LammpsSession&) = delete;
  LammpsSession& operator=(const LammpsSession&) = delete;

  // Input commands, one line each, as an input script would give them.
  void run(const std::vector<std::string>& commands) const {
    for (const auto& command : commands) lmp->input->one(command);
  }
};

}  // namespace ellc_lammps
