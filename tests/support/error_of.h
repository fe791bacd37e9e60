#pragma once
// The message of the E that f throws ("(no exception)" when it throws none), for tests that compare
// error messages word for word.
#include <exception>
#include <functional>
#include <string>

namespace cgtmo::test {

template <class E = std::exception>
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace cgtmo::test
