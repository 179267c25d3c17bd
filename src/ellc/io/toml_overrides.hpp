#pragma once
// Command-line overrides of a TOML input: `--set calendering.speed=0.025` edits the parsed table
// before it is validated, so a study varies one entry without copying or editing the file (and
// without a sed that matches `speed =` in the wrong table). The reader then checks the result like
// any file, naming the field.

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace ellc {

// Applies each "KEY=VALUE" in order. KEY is a dotted path of tables ending in a key
// (`walls.material.poisson_ratio`); tables missing on the way are created. VALUE is a TOML value
// (`0.025`, `true`, `"servo"`, `[100, 100]`). Throws InputError naming `option` and the entry when
// it is not of that form, or when the path runs through something that is not a table.
void apply_toml_overrides(toml::table& root, const std::vector<std::string>& overrides,
                          const std::string& option = "--set");

// `source` followed by the overrides as they would be typed (" --set a=1 --set b=2"), for messages
// and summaries that must say which input a run read.
[[nodiscard]] std::string describe_overrides(const std::string& source, const std::vector<std::string>& overrides,
                                             const std::string& option = "--set");

}  // namespace ellc
