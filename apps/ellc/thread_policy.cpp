#include "thread_policy.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "ellc/engine/cpu_load.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ellc::cli {

void prefer_short_spinning() {
#if defined(__linux__) && defined(_OPENMP)
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  // Under valgrind /proc/self/exe is valgrind's tool, which refuses to be started directly: the
  // re-executed run would end at once ("You cannot run ... directly"). Run as we are instead.
  if (const char* preload = std::getenv("LD_PRELOAD"); preload != nullptr && std::strstr(preload, "vgpreload")) return;
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(cmdline)), std::istreambuf_iterator<char>());
  std::vector<std::string> words;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = text.find('\0', start);
    words.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (words.empty()) return;
  std::vector<char*> arguments;
  for (auto& word : words) arguments.push_back(word.data());
  arguments.push_back(nullptr);
  setenv("GOMP_SPINCOUNT", "1000", 1);
  std::fflush(nullptr);
  execv("/proc/self/exe", arguments.data());  // returns only on failure: then run as we are
#endif
}

void cap_threads_at_cpu_quota() {
#ifdef _OPENMP
  if (std::getenv("OMP_NUM_THREADS") != nullptr) return;  // the user's count
  const int most = omp_get_max_threads();
  const int within = engine::threads_within_quota(most, engine::process_cpu_quota());
  if (within < most) omp_set_num_threads(within);
#endif
}

}  // namespace ellc::cli
