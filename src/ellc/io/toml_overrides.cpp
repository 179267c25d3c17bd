#include "ellc/io/toml_overrides.hpp"

#include <string_view>

#include "ellc/io/input_error.hpp"

namespace ellc {

namespace {

constexpr std::string_view kKeyForm =
    "KEY=VALUE with KEY a dotted path of bare TOML keys, e.g. calendering.speed=0.025";

[[noreturn]] void fail(const std::string& option, const std::string& entry, std::string_view expected) {
  throw InputError("", option + " " + entry + ": expected " + std::string(expected));
}

bool bare_key(std::string_view key) {
  if (key.empty()) return false;
  for (const char c : key)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
      return false;
  return true;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_path(std::string_view key, const std::string& option, const std::string& entry) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string_view part = key.substr(start, dot == std::string_view::npos ? dot : dot - start);
    if (!bare_key(part)) fail(option, entry, kKeyForm);
    parts.emplace_back(part);
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

// The value as TOML: parsed as the right-hand side of an assignment, so that anything a file may
// hold there (numbers, strings, booleans, arrays, inline tables) is accepted and nothing else.
toml::node_view<toml::node> parse_value(toml::table& holder, std::string_view value, const std::string& option,
                                        const std::string& entry) {
  try {
    holder = toml::parse("value = " + std::string(value), option);
  } catch (const toml::parse_error&) {
    fail(option, entry, "KEY=VALUE with VALUE a TOML value: a number, true or false, a \"quoted string\", an [array]");
  }
  if (holder.size() != 1)  // e.g. `x=1\ny = 2`: one value per --set
    fail(option, entry, "KEY=VALUE with one TOML value");
  return holder["value"];
}

}  // namespace

void apply_toml_overrides(toml::table& root, const std::vector<std::string>& overrides, const std::string& option) {
  for (const std::string& entry : overrides) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos) fail(option, entry, kKeyForm);
    const std::vector<std::string> path = split_path(trimmed(std::string_view(entry).substr(0, equals)), option, entry);
    toml::table holder;
    const auto value = parse_value(holder, trimmed(std::string_view(entry).substr(equals + 1)), option, entry);
    toml::table* table = &root;
    std::string reached;
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
      reached += (k == 0 ? "" : ".") + path[k];
      toml::node* next = table->get(path[k]);
      if (next == nullptr) next = &table->insert(path[k], toml::table{}).first->second;
      table = next->as_table();
      if (table == nullptr)
        fail(option, entry,
             "a path through tables, but " + reached + " is not a table (an array of tables such as [[species]] " +
                 "cannot be reached by " + option + ")");
    }
    table->insert_or_assign(path.back(), *value.node());
  }
}

std::string describe_overrides(const std::string& source, const std::vector<std::string>& overrides,
                               const std::string& option) {
  std::string text = source;
  for (const std::string& entry : overrides) text += " " + option + " " + entry;
  return text;
}

}  // namespace ellc
