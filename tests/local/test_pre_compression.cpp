// The scene-linear pre-compression's curve (src/cgtmo/local/pre_compression.cpp): where the base's
// maximum lands, the knees, continuity of value and slope, monotonicity, and the floor of the target.
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/local/pre_compression.h"

using namespace cgtmo::local;

namespace {
double mapped(const PreCompression& c, double u) { return u + c.log2_gain(u); }
double slope(const PreCompression& c, double u) {
  const double h = 1e-5;
  return (mapped(c, u + h) - mapped(c, u - h)) / (2 * h);
}
}  // namespace

TEST(PreCompression, MaximumLandsAtTheTargetAboveTheGrey) {
  // Lw_a two stops under 0.18, white 5.5 stops above 0.18: the target is 7.5 stops above Lw_a.
  const double lw_a = kSceneLinearGrey / 4;
  const PreCompression c = plan_pre_compression(12.0, lw_a, 5.5, 3.0);
  EXPECT_NEAR(c.target, 7.5, 1e-12);
  EXPECT_NEAR(c.knee_high, 0.75 * 7.5, 1e-12);
  EXPECT_NEAR(mapped(c, 12.0), 7.5, 1e-9);
  EXPECT_NEAR(slope(c, c.knee_high + 1e-4), 1.0, 1e-3);  // slope 1 where the shoulder starts
  EXPECT_NEAR(slope(c, -c.knee_low - 1e-4), 1.0, 1e-3);  // and where the toe starts
  // Between the knees nothing moves: Lw_a (u = 0) and mid-tones are kept.
  for (double u = -c.knee_low; u <= c.knee_high; u += 0.25) EXPECT_EQ(c.log2_gain(u), 0.0) << u;
}

TEST(PreCompression, MonotoneAndTheShadowsStayAboveTheirFloor) {
  const PreCompression c = plan_pre_compression(16.0, 0.02, 5.5, 3.0);
  double prev = mapped(c, -40.0);
  EXPECT_GT(prev, -3.0);  // 40 stops under Lw_a still lands within 3 stops of it
  for (double u = -40.0; u <= 16.0; u += 0.01) {
    const double m = mapped(c, u);
    EXPECT_GT(m, prev - 1e-12) << u;
    EXPECT_GT(slope(c, u), 0.0) << u;
    prev = m;
  }
}

TEST(PreCompression, NothingToDoWhenTheRangeFits) {
  const PreCompression c = plan_pre_compression(3.0, kSceneLinearGrey, 5.5, 0.0);
  EXPECT_EQ(c.k_high, 0.0);
  EXPECT_EQ(c.k_low, 0.0);
  for (double u = -20; u <= 3; u += 0.5) EXPECT_EQ(c.log2_gain(u), 0.0);
}

TEST(PreCompression, TargetIsAtLeastOneStopAboveLwA) {
  // A render exposed far above the grey: the white would lie under Lw_a; the target stays 1 stop up.
  const PreCompression c = plan_pre_compression(6.0, kSceneLinearGrey * 1024, 5.5, 3.0);
  EXPECT_NEAR(c.target, 1.0, 1e-12);
  EXPECT_NEAR(mapped(c, 6.0), 1.0, 1e-9);
}
