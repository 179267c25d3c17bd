// ELLC_ASSERT as this build configures it: on in Debug and sanitizer builds, compiled out in
// Release (NDEBUG without ELLC_ENABLE_ASSERTS).

#include <gtest/gtest.h>

#include "ellc/assert.hpp"

namespace {

TEST(Assert, FollowsTheBuildType) {
#if defined(NDEBUG) && !defined(ELLC_ENABLE_ASSERTS)
  constexpr int kExpected = 0;
#else
  constexpr int kExpected = 1;
#endif
  EXPECT_EQ(ELLC_ASSERTS_ENABLED, kExpected);
  int evaluations = 0;
  ELLC_ASSERT(++evaluations > 0, "counts its evaluations");
  EXPECT_EQ(evaluations, kExpected);
}

}  // namespace
