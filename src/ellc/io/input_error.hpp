#pragma once
// Bad input is reported as one sentence that names the field, the value seen and what was
// expected. Tools catch InputError at the top and exit with code 2.

#include <stdexcept>
#include <string>

namespace ellc {

class InputError : public std::runtime_error {
 public:
  // e.g. InputError("case.toml", "body_I.semi_axes[1]", "-2", "a finite number > 0")
  InputError(const std::string& source, const std::string& field, const std::string& value,
             const std::string& expected);
  // A message already in that form (e.g. from a validation_error() function).
  InputError(const std::string& source, const std::string& message);
};

// Formats a double for messages: shortest form that round-trips.
[[nodiscard]] std::string format_number(double value);

}  // namespace ellc
