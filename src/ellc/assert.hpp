#pragma once
// ELLC_ASSERT(condition, message): a check of an invariant of the code itself (never of user
// input: bad input is an InputError that names the field, see src/ellc/io/input_error.hpp).
//
// Active when NDEBUG is not defined (Debug builds) or when ELLC_ENABLE_ASSERTS is defined (the
// sanitizer builds of scripts/sanitizers.sh, -DELLC_SANITIZE=...). There a false condition
// prints "FILE:LINE: ELLC_ASSERT(condition) failed: message" to stderr and aborts, so a test
// stops at the step that broke the invariant instead of drifting into wrong numbers. Usable in
// noexcept code: nothing is thrown.
//
// In a Release build (NDEBUG without ELLC_ENABLE_ASSERTS) the condition is not evaluated and no
// code is emitted: it only appears as an unevaluated operand of sizeof, which keeps the
// variables it names "used" (no -Wunused warnings) and still has the compiler check it. A check
// that needs a loop goes into a function returning bool, called inside the condition.
//
// Outside the layers of src/CMakeLists.txt: any layer may include it; it includes nothing of ellc.

#include <cstdio>
#include <cstdlib>

#if !defined(NDEBUG) || defined(ELLC_ENABLE_ASSERTS)
#define ELLC_ASSERTS_ENABLED 1
#else
#define ELLC_ASSERTS_ENABLED 0
#endif

namespace ellc::assert_detail {

[[noreturn, gnu::cold, gnu::noinline]] inline void fail(const char* file, int line, const char* condition,
                                                        const char* message) noexcept {
  std::fprintf(stderr, "%s:%d: ELLC_ASSERT(%s) failed: %s\n", file, line, condition, message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace ellc::assert_detail

#if ELLC_ASSERTS_ENABLED
#define ELLC_ASSERT(condition, message)                \
  (static_cast<bool>(condition) ? static_cast<void>(0) \
                                : ::ellc::assert_detail::fail(__FILE__, __LINE__, #condition, message))
#else
#define ELLC_ASSERT(condition, message) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif
