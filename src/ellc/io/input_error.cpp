#include "ellc/io/input_error.hpp"

#include <cstdio>

namespace ellc {

namespace {
std::string prefixed(const std::string& source, const std::string& message) {
  return source.empty() ? message : source + ": " + message;
}
}  // namespace

InputError::InputError(const std::string& source, const std::string& field, const std::string& value,
                       const std::string& expected)
    : std::runtime_error(prefixed(source, field + " = " + value + ": expected " + expected)) {}

InputError::InputError(const std::string& source, const std::string& message)
    : std::runtime_error(prefixed(source, message)) {}

std::string format_number(double value) {
  char buffer[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    double parsed = 0.0;
    if (std::sscanf(buffer, "%lf", &parsed) == 1 && parsed == value) break;
  }
  return buffer;
}

}  // namespace ellc
