#include "cgtmo/sequence/temporal.h"

#include <cmath>

namespace cgtmo::sequence {

std::vector<double> smooth_in_stops(const std::vector<double>& values, double tau) {
  const std::size_t n = values.size();
  std::vector<double> out(values);
  std::vector<bool> usable(n);
  for (std::size_t i = 0; i < n; ++i) usable[i] = std::isfinite(values[i]) && values[i] > 0;
  if (!(tau > 0)) return out;
  const long radius = long(std::ceil(3.0 * tau));
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0, wsum = 0;
    for (long d = -radius; d <= radius; ++d) {
      const long j = long(i) + d;
      if (j < 0 || j >= long(n) || !usable[std::size_t(j)]) continue;
      const double w = std::exp(-0.5 * double(d * d) / (tau * tau));
      sum += w * std::log2(values[std::size_t(j)]);
      wsum += w;
    }
    if (wsum > 0) out[i] = std::exp2(sum / wsum);
  }
  return out;
}

double mean_abs_step_stops(const std::vector<double>& v) {
  double sum = 0;
  std::size_t k = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (!(v[i] > 0 && v[i - 1] > 0)) continue;
    sum += std::abs(std::log2(v[i] / v[i - 1]));
    ++k;
  }
  return k ? sum / double(k) : 0.0;
}

}  // namespace cgtmo::sequence
