#pragma once
// Numbers in --explain lines: five significant digits, as the statistics and guide decisions print them.
#include <sstream>
#include <string>

namespace cgtmo::local {

inline std::string explain_number(double v) {
  std::ostringstream o;
  o.precision(5);
  o << v;
  return o.str();
}

}  // namespace cgtmo::local
