#include "plot_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

namespace ellc::cli {

namespace {
std::string environment_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}
}  // namespace

void run_python_plot(const std::vector<std::string>& arguments) {
  // ELLC_PYTHON and ELLC_PYTHON_DIR override the build-time defaults (e.g. for an installed tree).
  const std::string python = environment_or("ELLC_PYTHON", ELLC_PYTHON);
  const std::string package_dir = environment_or("ELLC_PYTHON_DIR", ELLC_PYTHON_SOURCE_DIR);
  std::vector<std::string> command{python, "-m", "ellc.plots"};
  command.insert(command.end(), arguments.begin(), arguments.end());

  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot start the plotting process");
  if (child == 0) {
    std::string path = package_dir;
    if (const char* existing = std::getenv("PYTHONPATH"); existing != nullptr && *existing != '\0')
      path += std::string(":") + existing;
    setenv("PYTHONPATH", path.c_str(), 1);
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
