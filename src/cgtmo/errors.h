#pragma once
// Two error kinds, because the CLI maps them onto two exit codes (2: usage, 1: data).
#include <stdexcept>
#include <string>

namespace cgtmo {

// The request is wrong: unknown operator or parameter, value out of range, bad path.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The data is wrong: unreadable, truncated or corrupt file, missing channels.
struct DataError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cgtmo
