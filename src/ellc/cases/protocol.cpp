#include "ellc/cases/protocol.hpp"

namespace ellc {

std::vector<double> protocol_overlaps(const std::vector<double>& waypoints, long points_per_segment) {
  std::vector<double> path;
  if (waypoints.empty()) return path;
  path.reserve(1 + (waypoints.size() - 1) * static_cast<std::size_t>(points_per_segment));
  path.push_back(waypoints.front());
  for (std::size_t segment = 1; segment < waypoints.size(); ++segment) {
    const double start = waypoints[segment - 1];
    const double end = waypoints[segment];
    for (long step = 1; step < points_per_segment; ++step)
      path.push_back(start + (end - start) * static_cast<double>(step) / static_cast<double>(points_per_segment));
    path.push_back(end);  // exact, not start + (end − start)·1
  }
  return path;
}

}  // namespace ellc
