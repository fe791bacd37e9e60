#pragma once
// Helpers shared by the operator tests: run a registry operator through the real pipeline
// (operators::tonemap) on a few pixels and read the result back.
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "cgtmo/operators/apply.h"

namespace cgtmo::operators::test {

using RGB = std::array<float, 3>;
using Params = std::map<std::string, std::string>;

// Tone-maps an RGB image given as a list of pixels (a 1xN image) and returns it.
inline std::vector<RGB> run(const std::string& op, std::vector<RGB> px, const Params& params = {},
                            double exposure_ev = 0.0) {
  ToneMapRequest req;
  req.op = op;
  req.params = params;
  req.exposure_ev = exposure_ev;
  tonemap(px.empty() ? nullptr : px[0].data(), px.size(), 3, req);
  return px;
}

// One pixel.
inline RGB run1(const std::string& op, RGB c, const Params& params = {}) { return run(op, {c}, params)[0]; }

// The output of a grey input (first channel), for operators whose parameters do not default
// from the image (or are given).
inline double grey(const std::string& op, double x, const Params& params = {}) {
  const float v = float(x);
  return run1(op, {v, v, v}, params)[0];
}

// Log-spaced sweep from lo to hi, n points.
inline std::vector<double> log_sweep(double lo, double hi, int n) {
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) xs.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
  return xs;
}

}  // namespace cgtmo::operators::test
