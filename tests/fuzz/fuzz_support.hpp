#pragma once
// Shared by the fuzz harnesses (tests/fuzz/README.md): what counts as a finding besides a crash
// or a sanitizer report. A harness rejects bad input through the readers (InputError is the
// expected answer); a finding is a non-finite number the tool would have printed, or any other
// broken promise, reported and then aborted on so that libFuzzer keeps the input.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace ellc::fuzz {

[[noreturn]] inline void finding(const char* what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what);
  std::abort();
}

inline void require_finite(double value, const char* what) {
  if (!std::isfinite(value)) finding(what);
}

inline std::string_view text_of(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace ellc::fuzz
