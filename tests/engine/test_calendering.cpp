// The calendering protocol on examples/calendering_quick.toml: the layer springs back after
// release, and less than the same layer with a purely elastic (Hertz) law.

#include <gtest/gtest.h>

#include "engine_support.hpp"

namespace ellc::engine {
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

TEST(EngineCalendering, SpringbackPositiveAndSmallerThanElastic) {
  const std::string text = quick_scenario_text();
  const RunSummary plastic = calender(text);
  const RunSummary elastic = calender(testing::replace_line(text, "normal =", "normal = \"hertz\""));
  RecordProperty("springback_becker_kamlah_percent", std::to_string(plastic.springback_percent));
  RecordProperty("springback_hertz_percent", std::to_string(elastic.springback_percent));
  EXPECT_GT(plastic.max_pressure, 200.0);  // the target pressure was reached
  EXPECT_GT(plastic.springback_percent, 0.0);
  EXPECT_LT(plastic.springback_percent, elastic.springback_percent);
  EXPECT_GT(plastic.plastic_dissipation, 0.0);
  EXPECT_EQ(elastic.plastic_dissipation, 0.0);
  EXPECT_LT(plastic.final_porosity, plastic.loaded_porosity + 1.0);
  EXPECT_GT(plastic.final_thickness, plastic.loaded_thickness);
  EXPECT_EQ(plastic.narrow_phase_failures, 0U);
}

}  // namespace
}  // namespace ellc::engine
