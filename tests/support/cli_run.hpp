#pragma once
// Runs the `ellc` CLI of this build (ELLC_CLI_PATH, set by the test target) with `arguments` and
// returns its exit code and everything it printed (stdout and stderr).

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace ellc::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout + stderr
};

inline CliRun run_cli(const std::string& arguments) {
  const std::string command = std::string(ELLC_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

}  // namespace ellc::test
