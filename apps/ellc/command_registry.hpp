#pragma once
// Subcommands register themselves, so adding one (`ellc dem`, `ellc fit`, ...) is one new source
// file plus a line in its apps/ellc/<name>.cmake fragment; main.cpp never changes.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ellc::cli {

using CommandSetup = std::function<void(CLI::App& root)>;

inline std::vector<CommandSetup>& command_setups() {
  static std::vector<CommandSetup> setups;
  return setups;
}

struct RegisterCommand {
  explicit RegisterCommand(CommandSetup setup) { command_setups().push_back(std::move(setup)); }
};

// `--set KEY=VALUE`, repeatable, for the commands that read a scenario (dem, export-lammps): the
// same study with one entry changed, without editing the file (io/toml_overrides.hpp).
inline void add_scenario_overrides(CLI::App& command, std::vector<std::string>& overrides) {
  command
      .add_option("--set", overrides,
                  "Replace a scenario entry before it is checked, e.g. --set calendering.speed=0.025 "
                  "(repeatable; KEY is table.key, VALUE is TOML). --restart needs the same --set entries")
      ->expected(1)  // one KEY=VALUE per --set, so a positional after it is not swallowed
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace ellc::cli
