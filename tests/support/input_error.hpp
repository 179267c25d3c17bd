#pragma once
// For the tests of bad input: run the code, get the message of the InputError it threw.

#include <string>

#include "ellc/io/input_error.hpp"

namespace ellc::test {

// The message of the InputError thrown by `action`, or "" if it threw none. Other exceptions
// pass through (and fail the test).
template <typename Action>
[[nodiscard]] std::string input_error_message(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace ellc::test
