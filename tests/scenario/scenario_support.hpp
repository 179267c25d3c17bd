#pragma once
// Shared helpers of the scenario tests: the quick calendering scenario and in-memory runs.

#include <string>

#include "ellc/scenario/scenario.hpp"
#include "ellc/scenario/scenario_runner.hpp"

namespace ellc::scenario::testing {

// Text of examples/calendering_quick.toml, optionally with one line replaced.
[[nodiscard]] std::string quick_scenario_text();
[[nodiscard]] std::string replace_line(std::string text, const std::string& starts_with, const std::string& line);
[[nodiscard]] Scenario quick_scenario(const std::string& text);

// Options for runs that write nothing to disk.
[[nodiscard]] RunOptions in_memory(std::size_t parallel_threshold = 0);

}  // namespace ellc::scenario::testing
