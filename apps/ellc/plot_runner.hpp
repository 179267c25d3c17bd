#pragma once
// Plots are drawn by the Python package in python/ellc (matplotlib through Debian's
// /usr/bin/python3); the C++ tools write CSV and call it.

#include <string>
#include <vector>

namespace ellc::cli {

// Runs `python3 -m ellc.plots <arguments...>`; throws std::runtime_error when it fails.
void run_python_plot(const std::vector<std::string>& arguments);

}  // namespace ellc::cli
