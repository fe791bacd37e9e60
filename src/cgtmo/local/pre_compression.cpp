#include "cgtmo/local/pre_compression.h"
#include "cgtmo/util/repro_math.h"

#include <algorithm>
#include <cmath>

namespace cgtmo::local {

namespace {
// The shoulder starts 3/4 of the way from Lw_a to the target, the toe halfway to the shadows'
// floor. Measured on the committed scenes under Filmic and our agx (docs/cgtmo.md, section 11):
// a shoulder from halfway (or from Lw_a) took local contrast out of lit walls and lowered TMQI;
// a toe knee nearer Lw_a flattened the mid-tones of bright scenes (colored-lights).
constexpr double kShoulderKnee = 0.75;
constexpr double kToeKnee = 0.5;
constexpr double kMinTargetStops = 1.0;
}  // namespace

PreCompression plan_pre_compression(double headroom, double lw_a, double white_stops, double shadow_stops) {
  PreCompression c;
  c.target = std::max(white_stops + repro::log2(kSceneLinearGrey / lw_a), kMinTargetStops);
  c.knee_high = kShoulderKnee * c.target;
  if (headroom > c.target) c.k_high = (headroom - c.target) / ((headroom - c.knee_high) * (c.target - c.knee_high));
  if (shadow_stops > 0) {
    c.knee_low = kToeKnee * shadow_stops;
    c.k_low = 1.0 / (shadow_stops - c.knee_low);
  }
  return c;
}

}  // namespace cgtmo::local
