#pragma once
// The work a scenario asks for, estimated from the scenario file alone before anything is built
// (docs/input_limits.md): the time step, the number of steps, the memory and the size of the
// outputs. `ellc dem` prints it and refuses a run beyond the stated limits unless --force is given;
// a run the engine cannot represent at all (a cell grid beyond 32-bit indices, a non-finite plan)
// is refused even then.

#include <cstdint>
#include <string>
#include <vector>

#include "ellc/scenario/scenario.hpp"

namespace ellc::scenario {

// The limits beyond which a run needs --force. The largest shipped example (examples/calendering.toml)
// plans ~2·10⁶ steps, ~60 MB and ~1 GB of output: the limits leave a factor of 50 or more.
inline constexpr double kMaxPlannedSteps = 1e8;
inline constexpr double kMaxPlannedMemoryBytes = 16.0 * 1024 * 1024 * 1024;  // 16 GiB
inline constexpr double kMaxPlannedOutputBytes = 50e9;                       // 50 GB
// Refused even with --force: the packing's insertion grid and the engine's cell grid index their
// cells with 32-bit integers.
inline constexpr double kMaxGridCells = 2147483647.0;

struct RunPlan {
  double time_step = 0.0;                  // µs: [time] dt, or safety × the Rayleigh time of the smallest semi-axis
  double smallest_semi_axis = 0.0;         // µm, the smallest the packing spec can draw
  double layer_height = 0.0;               // µm: the insertion region the particles start in
  double simulated_time = 0.0;             // µs, at most (settle, load, hold, unload, relax at their longest)
  double steps = 0.0;                      // at most
  double memory_bytes = 0.0;               // particles, pair list and the cell grids
  double output_bytes = 0.0;               // CSV, VTK frames, checkpoint, summary
  double grid_cells = 0.0;                 // cells of the dense cell grid over box × layer height
  std::vector<std::string> beyond_limits;  // each names the estimate, the limit and the fields behind it
  std::vector<std::string> impossible;     // refused even with --force
};

// Never throws for a scenario read_scenario accepted; non-finite estimates land in `impossible`.
[[nodiscard]] RunPlan plan_run(const Scenario& scenario);

// One line: "dt = 0.0021 µs, at most 1.2e+06 steps (2500 µs simulated), memory ~25 MB, output ~12 MB".
[[nodiscard]] std::string describe_plan(const RunPlan& plan);

// A number of bytes in short form: "812 B", "25 MB", "3.9 GB".
[[nodiscard]] std::string format_bytes(double bytes);

}  // namespace ellc::scenario
