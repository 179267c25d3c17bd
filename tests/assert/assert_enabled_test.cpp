// ELLC_ASSERT switched on by ELLC_ENABLE_ASSERTS even where NDEBUG is defined (the sanitizer
// builds): a true condition is evaluated once and passes, a false one prints FILE:LINE, the
// condition and the message, and aborts.

#include <gtest/gtest.h>

#ifndef ELLC_ENABLE_ASSERTS
#define ELLC_ENABLE_ASSERTS
#endif
#include "ellc/assert.hpp"

namespace {

static_assert(ELLC_ASSERTS_ENABLED == 1);

TEST(AssertEnabled, TrueConditionIsEvaluatedOnce) {
  int evaluations = 0;
  ELLC_ASSERT(++evaluations == 1, "evaluated once");
  EXPECT_EQ(evaluations, 1);
}

TEST(AssertEnabledDeathTest, FalseConditionAbortsWithFileLineConditionAndMessage) {
  const int contacts = 3;
  EXPECT_DEATH(ELLC_ASSERT(contacts < 2, "at most two contacts"),
               R"(assert_enabled_test\.cpp:[0-9]+: ELLC_ASSERT\(contacts < 2\) failed: at most two contacts)");
}

}  // namespace
