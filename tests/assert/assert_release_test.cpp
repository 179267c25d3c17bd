// ELLC_ASSERT as a Release build sees it (NDEBUG, no ELLC_ENABLE_ASSERTS), whatever this build's
// type: the condition is not evaluated, so a false one neither aborts nor has side effects.

#include <gtest/gtest.h>

#ifndef NDEBUG
#define NDEBUG
#endif
#undef ELLC_ENABLE_ASSERTS
#include "ellc/assert.hpp"

namespace {

static_assert(ELLC_ASSERTS_ENABLED == 0);

int calls = 0;
bool counted_false() {
  ++calls;
  return false;
}

TEST(AssertRelease, ConditionIsNotEvaluated) {
  ELLC_ASSERT(counted_false(), "compiled out: never evaluated, never aborts");
  EXPECT_EQ(calls, 0);
}

// In a constant expression: the compiled-out macro is a constant expression of type void.
constexpr int checked_square(int x) {
  ELLC_ASSERT(x >= 0, "non-negative");
  return x * x;
}
static_assert(checked_square(-3) == 9);

}  // namespace
