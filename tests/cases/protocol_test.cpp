// protocol_overlaps (ellc/cases/protocol.hpp): the overlaps `ellc curve` runs through the waypoints.
#include <gtest/gtest.h>

#include <vector>

#include "ellc/cases/protocol.hpp"

namespace {

TEST(Protocol, EveryWaypointOnceAndSegmentsSampledUniformly) {
  const std::vector<double> path = ellc::protocol_overlaps({0.0, 2.0, 1.0}, 4);
  const std::vector<double> expected{0.0, 0.5, 1.0, 1.5, 2.0, 1.75, 1.5, 1.25, 1.0};
  ASSERT_EQ(path.size(), expected.size());
  for (std::size_t i = 0; i < path.size(); ++i) EXPECT_DOUBLE_EQ(path[i], expected[i]) << i;
}

TEST(Protocol, OneWaypointIsItselfAndNoneIsEmpty) {
  EXPECT_EQ(ellc::protocol_overlaps({0.3}, 7), std::vector<double>{0.3});
  EXPECT_TRUE(ellc::protocol_overlaps({}, 7).empty());
}

}  // namespace
