#pragma once
// Displacement protocols: waypoints of overlap, each segment sampled uniformly.

#include <vector>

namespace ellc {

// Path through the waypoints: the first waypoint, then `points_per_segment` points per segment,
// the last of which is the segment's end waypoint, so every waypoint appears exactly once per visit.
[[nodiscard]] std::vector<double> overlap_path(const std::vector<double>& waypoints, long points_per_segment);

}  // namespace ellc
