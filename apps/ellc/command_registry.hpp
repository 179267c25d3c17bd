#pragma once
// Subcommands register themselves, so adding one (`ellc dem`, `ellc fit`, ...) is one new source
// file plus a line in its apps/ellc/<name>.cmake fragment; main.cpp never changes.

#include <CLI/CLI.hpp>

#include <functional>
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

}  // namespace ellc::cli
