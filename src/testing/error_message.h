// For tests of bad input: what an action throws, so that a test can compare
// the message with the exact text users will read.
#pragma once

#include <string>

#include "aapat/core/geometry.h"

namespace aapat::testing {

// The message of the Error that f throws, or "no error" when it returns.
template <class F>
std::string error_message(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// The parameter a ParameterError from f names, "error" for another Error,
// "accepted" when f returns: which setting a validation blamed.
template <class F>
std::string error_parameter(F&& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.parameter();
  } catch (const Error&) {
    return "error";
  }
  return "accepted";
}

}  // namespace aapat::testing
