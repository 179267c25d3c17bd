// The calendering protocol on examples/calendering_quick.toml: the layer springs back after
// release, and less than the same layer with a purely elastic (Hertz) law.

#include <gtest/gtest.h>

#include "scenario_support.hpp"

namespace ellc::scenario {
namespace {

using testing::in_memory;
using testing::quick_scenario;
using testing::quick_scenario_text;

RunSummary calender(const std::string& text) {
  ScenarioRunner runner(quick_scenario(text), in_memory(512));
  runner.advance(200'000);
  EXPECT_TRUE(runner.done());
  return runner.summary();
}

// Elastic reference: the same layer with plain Hertz. Plastic runs: NMC (Y = 7900 MPa, the example)
// and a softer Y = 3000 MPa, where the plastic flattening of the contacts dominates the recovery.
// Pressed to 400 MPa rather than the example's 200: at 200 MPa NMC barely yields, and its
// springback (5.63 %) sits within the run-to-run scatter of the elastic one (5.72 %); at 400 MPa
// it is 8.4 % against 9.2 % (Y = 3000: 4.5 %).
TEST(EngineCalendering, SpringbackPositiveAndSmallerThanElastic) {
  const std::string text = testing::replace_line(quick_scenario_text(), "target_pressure", "target_pressure = 400.0");
  const RunSummary elastic = calender(testing::replace_line(text, "normal =", "normal = \"hertz\""));
  const RunSummary nmc = calender(text);
  const RunSummary soft = calender(testing::replace_line(text, "yield_stress", "yield_stress = 3000.0"));
  RecordProperty("springback_hertz_percent", std::to_string(elastic.springback_percent));
  RecordProperty("springback_nmc_percent", std::to_string(nmc.springback_percent));
  RecordProperty("springback_y3000_percent", std::to_string(soft.springback_percent));
  for (const RunSummary* run : {&elastic, &nmc, &soft}) {
    EXPECT_GT(run->max_pressure, 400.0 * 0.99);  // the target pressure was reached
    EXPECT_GT(run->final_thickness, run->loaded_thickness);
    EXPECT_EQ(run->narrow_phase_failures, 0U);
  }
  EXPECT_GT(nmc.springback_percent, 0.0);
  EXPECT_LT(nmc.springback_percent, elastic.springback_percent);
  EXPECT_GT(soft.springback_percent, 0.0);
  EXPECT_LT(soft.springback_percent, 0.8 * elastic.springback_percent);
  EXPECT_EQ(elastic.plastic_dissipation, 0.0);
  EXPECT_GT(nmc.plastic_dissipation, 0.0);
  EXPECT_GT(soft.plastic_dissipation, nmc.plastic_dissipation);
}

}  // namespace
}  // namespace ellc::scenario
