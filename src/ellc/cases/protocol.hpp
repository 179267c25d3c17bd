#pragma once
// Displacement protocols: waypoints of overlap, each segment sampled uniformly.

#include <vector>

namespace ellc {

// The overlaps of a protocol, in order: the first waypoint, then `points_per_segment` points per
// segment, the last of which is the segment's end waypoint, so every waypoint appears exactly once
// per visit. This is the path `ellc curve` runs; the law along it is evaluate_along_path()
// (ellc/law/law_along_path.hpp).
[[nodiscard]] std::vector<double> protocol_overlaps(const std::vector<double>& waypoints, long points_per_segment);

}  // namespace ellc
