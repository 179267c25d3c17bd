// ellc: command-line tools for the Becker–Kamlah elastoplastic ellipsoid contact law.
// Exit codes: 0 success, 1 internal/runtime failure, 2 bad input (the message names the field).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <functional>
#include <string>

#include "command_registry.hpp"
#include "ellc/io/input_error.hpp"
#include "plot_runner.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ellc: normal contact force between elastoplastic ellipsoids (Becker & Kamlah)"};
  app.require_subcommand(1);
  // The version, and where the plots' Python package comes from (an installed CLI uses its own).
  app.set_version_flag("--version", std::function<std::string()>([] {
    return std::string("ellc ") + ELLC_VERSION + "\n" + ellc::cli::plot_setup_description();
  }));
  for (const auto& setup : ellc::cli::command_setups()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  } catch (const ellc::InputError& error) {
    std::fprintf(stderr, "ellc: error: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "ellc: failed: %s\n", error.what());
    return 1;
  }
  return 0;
}
