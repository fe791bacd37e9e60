#include "cgtmo/sequence/temporal.h"
#include "cgtmo/util/repro_math.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace cgtmo::sequence {

std::vector<double> smooth_in_stops_at(const std::vector<long>& frames, const std::vector<double>& values,
                                       const std::vector<long>& at, double tau) {
  std::vector<double> out(at.size(), NAN);
  const std::size_t n = std::min(frames.size(), values.size());
  if (!(tau > 0)) {
    for (std::size_t i = 0; i < at.size(); ++i) {
      const auto it = std::lower_bound(frames.begin(), frames.begin() + long(n), at[i]);
      if (it != frames.begin() + long(n) && *it == at[i]) out[i] = values[std::size_t(it - frames.begin())];
    }
    return out;
  }
  const long radius = long(std::ceil(3.0 * std::min(tau, 1e9)));
  for (std::size_t i = 0; i < at.size(); ++i) {
    double sum = 0, wsum = 0;
    // Neighbours in frame order, as the dense loop visited them (so contiguous shots give the
    // same sums, to the last bit).
    for (auto it = std::lower_bound(frames.begin(), frames.begin() + long(n), at[i] - radius);
         it != frames.begin() + long(n) && *it <= at[i] + radius; ++it) {
      const double v = values[std::size_t(it - frames.begin())];
      if (!(std::isfinite(v) && v > 0)) continue;
      const double d = double(*it - at[i]);
      const double w = repro::exp(-0.5 * (d * d) / (tau * tau));
      sum += w * repro::log2(v);
      wsum += w;
    }
    if (wsum > 0) out[i] = repro::exp2(sum / wsum);
  }
  return out;
}

std::vector<double> smooth_in_stops(const std::vector<double>& values, double tau) {
  std::vector<long> frames(values.size());
  std::iota(frames.begin(), frames.end(), 0L);
  std::vector<double> out = smooth_in_stops_at(frames, values, frames, tau);
  // A frame without a usable neighbour keeps its own value.
  for (std::size_t i = 0; i < out.size(); ++i)
    if (std::isnan(out[i])) out[i] = values[i];
  return out;
}

double mean_abs_step_stops(const std::vector<double>& v) {
  double sum = 0;
  std::size_t k = 0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (!(v[i] > 0 && v[i - 1] > 0)) continue;
    sum += std::abs(repro::log2(v[i] / v[i - 1]));
    ++k;
  }
  return k ? sum / double(k) : 0.0;
}

}  // namespace cgtmo::sequence
