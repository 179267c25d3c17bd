#include "plot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace ellc::cli {

namespace {
std::string environment_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

bool holds_plots(const std::filesystem::path& dir) {
  std::error_code error;
  return std::filesystem::is_regular_file(dir / "ellc" / "plots.py", error);
}

// The package folder of an installed CLI: ELLC_PYTHON_INSTALL_DIR relative to this executable's
// folder (or absolute).
std::filesystem::path installed_package_dir() {
  const std::filesystem::path installed{ELLC_PYTHON_INSTALL_DIR};
  if (installed.is_absolute()) return installed;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  return (self.parent_path() / installed).lexically_normal();
}

std::string python_interpreter() { return environment_or("ELLC_PYTHON", ELLC_PYTHON); }
}  // namespace

std::string plot_package_dir() {
  if (const char* dir = std::getenv("ELLC_PYTHON_DIR"); dir != nullptr && *dir != '\0') return dir;
  if (const auto installed = installed_package_dir(); !installed.empty() && holds_plots(installed))
    return installed.string();
  if (holds_plots(ELLC_PYTHON_SOURCE_DIR)) return ELLC_PYTHON_SOURCE_DIR;
  return {};
}

std::string plot_setup_description() {
  const std::string dir = plot_package_dir();
  return "plots: " + python_interpreter() + " -m ellc.plots, package " +
         (dir.empty() ? std::string("from the interpreter's sys.path") : "in " + dir);
}

void run_python_plot(const std::vector<std::string>& arguments) {
  // ELLC_PYTHON and ELLC_PYTHON_DIR override the build-time defaults.
  const std::string python = python_interpreter();
  const std::string package_dir = plot_package_dir();
  std::vector<std::string> command{python, "-m", "ellc.plots"};
  command.insert(command.end(), arguments.begin(), arguments.end());

  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot start the plotting process");
  if (child == 0) {
    std::string path = package_dir;
    if (const char* existing = std::getenv("PYTHONPATH"); existing != nullptr && *existing != '\0')
      path += (path.empty() ? "" : ":") + std::string(existing);
    if (!path.empty()) setenv("PYTHONPATH", path.c_str(), 1);
    setenv("MPLBACKEND", "Agg", 1);
    std::vector<char*> argv;
    for (auto& word : command) argv.push_back(word.data());
    argv.push_back(nullptr);
    execv(python.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("plotting with " + python + " -m ellc.plots failed (exit " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                             "); is python3-matplotlib installed? (scripts/setup.sh)");
}

}  // namespace ellc::cli
