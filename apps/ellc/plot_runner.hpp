#pragma once
// Plots are drawn by the Python package in python/ellc (matplotlib through Debian's
// /usr/bin/python3); the C++ tools write CSV and call it.

#include <string>
#include <vector>

namespace ellc::cli {

// Where `python3 -m ellc.plots` is imported from, first match:
//   1. the environment variable ELLC_PYTHON_DIR;
//   2. the installed package next to this executable (<prefix>/bin/../lib/python3/dist-packages);
//   3. the source tree the executable was built from (python/);
//   4. empty: the interpreter's own sys.path (e.g. /usr/lib/python3/dist-packages).
// 2 and 3 count only when they hold ellc/plots.py.
[[nodiscard]] std::string plot_package_dir();

// One line for `ellc --version`: the interpreter and the package folder the plots use.
[[nodiscard]] std::string plot_setup_description();

// Runs `python3 -m ellc.plots <arguments...>`; throws std::runtime_error when it fails.
void run_python_plot(const std::vector<std::string>& arguments);

}  // namespace ellc::cli
