#include "ellc/io/input_error.hpp"

#include <charconv>

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
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;  // shortest round-trip form
  return std::string(buffer, end);
}

}  // namespace ellc
