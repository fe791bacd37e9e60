// libFuzzer target: operator parameter parsing and validation (operators/params.cpp) and the
// camera-table parser (operators/camera_table.cpp). Input: "<op>\nkey=value\n..." or, when it
// starts with "DORF\n", a camera table. Built operators are run on a few pixels: the output must
// stay finite and in [0, 1] whatever parameters were accepted.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/camera_table.h"
#include "cgtmo/operators/registry.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  using namespace cgtmo::operators;
  if (in.rfind("DORF\n", 0) == 0) {
    try {
      const auto t = parse_dorf(in.substr(5), "fuzz");
      for (const auto& c : t)
        for (double e : {-1.0, 0.0, 0.3, 1.0, 2.0}) {
          const double v = sample_response(c, e);
          if (!(v >= 0.0 && v <= 1.0)) std::abort();
        }
    } catch (const cgtmo::DataError&) {
    }
    return 0;
  }
  std::size_t pos = in.find('\n');
  const std::string op = in.substr(0, pos);
  std::map<std::string, std::string> given;
  while (pos != std::string::npos) {
    const std::size_t next = in.find('\n', pos + 1);
    const std::string line = in.substr(pos + 1, next == std::string::npos ? std::string::npos : next - pos - 1);
    const auto eq = line.find('=');
    if (eq != std::string::npos && line.compare(0, eq, "table") != 0)  // no file access from fuzz input
      given[line.substr(0, eq)] = line.substr(eq + 1);
    pos = next;
  }
  try {
    const OperatorDef& def = find_operator(op);
    const ImageStats stats{3.0, 2.0, 0.5};
    auto ev = make_evaluator(def, given, &stats);
    float px[5 * 3] = {0, 0, 0, 0.18f, 0.18f, 0.18f, 1, 0, 0, 65504, 65504, 65504, 1e-30f, 2, 0.5f};
    ev->apply(px, 5, 3);
    for (float v : px)
      if (!(v >= 0.f && v <= 1.f)) std::abort();
  } catch (const cgtmo::UsageError&) {
  } catch (const cgtmo::DataError&) {
  }
  return 0;
}
