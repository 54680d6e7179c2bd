#pragma once
// Bad user input (a file, a config key, a device): one line naming it and the reason.
// Thrown only at the boundary (readers, parsers, CLI), never in algorithms.
#include <stdexcept>
#include <string>

namespace cosmos {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cosmos
