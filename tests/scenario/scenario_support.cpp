#include "scenario_support.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ellc::scenario::testing {

std::string quick_scenario_text() {
  std::ifstream file(std::string(ELLC_EXAMPLES_DIR) + "/calendering_quick.toml");
  if (!file) throw std::runtime_error("examples/calendering_quick.toml not found");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replace_line(std::string text, const std::string& starts_with, const std::string& line) {
  const auto at = text.find("\n" + starts_with);
  if (at == std::string::npos) throw std::runtime_error("no line starting with " + starts_with);
  const auto end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, line);
}

Scenario quick_scenario(const std::string& text) { return parse_scenario(text, "calendering_quick.toml"); }

RunOptions in_memory(std::size_t parallel_threshold) {
  RunOptions options;
  options.write_files = false;
  options.parallel_threshold = parallel_threshold;
  return options;
}

}  // namespace ellc::scenario::testing
