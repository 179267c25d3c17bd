#pragma once
// Values of the output files that are TOML documents (summary.txt, analysis.txt), written by
// hand so that the keys keep their order and their comments.

#include <string>
#include <string_view>

namespace ellc {

// A TOML float: the shortest round-trip form with a decimal point (1 would read as an integer),
// inf, -inf and nan as TOML spells them.
[[nodiscard]] std::string toml_float(double value);

// A TOML basic string: quotes and backslashes escaped; control characters (never in the prose
// this quotes) become spaces rather than break the document.
[[nodiscard]] std::string toml_string(std::string_view text);

}  // namespace ellc
