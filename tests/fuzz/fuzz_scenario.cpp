// Fuzz target: the scenario file of `ellc dem` (scenario/scenario_file.cpp). Bytes → TOML →
// validated Scenario → the planned work (run_plan.hpp) → for a small plan, the packing and three
// steps of the engine, in memory. A run that the plan accepts must end cleanly: finite
// observables, or one of the errors `ellc dem` reports (bad input, protocol, runaway).

#include <cstdint>
#include <stdexcept>

#include "ellc/io/input_error.hpp"
#include "ellc/scenario/run_plan.hpp"
#include "ellc/scenario/scenario_runner.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellc;
  using namespace ellc::scenario;
  try {
    const Scenario loaded = parse_scenario(fuzz::text_of(data, size), "fuzz_scenario.toml");
    const RunPlan plan = plan_run(loaded);
    if (!plan.impossible.empty() || !plan.beyond_limits.empty()) return 0;  // `ellc dem` stops here
    // Keep each input cheap: a few particles in a small grid.
    if (loaded.packing.count > 12 || plan.grid_cells > 4096 || !loaded.seeds.empty()) return 0;
    RunOptions options;
    options.write_files = false;
    ScenarioRunner runner(loaded, options);
    runner.advance(3);
    const auto& simulation = runner.simulation();
    fuzz::require_finite(simulation.kinetic_energy(), "non-finite kinetic energy after three steps");
    fuzz::require_finite(simulation.wall_pressure(engine::kTopWall), "non-finite plate pressure");
    fuzz::require_finite(simulation.gap(), "non-finite plate gap");
  } catch (const InputError&) {
  } catch (const ProtocolError&) {
  } catch (const engine::RunawayError&) {
  } catch (const std::runtime_error&) {  // the packing generator giving up on a box too full
  }
  return 0;
}
