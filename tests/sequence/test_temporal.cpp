#include "cgtmo/sequence/temporal.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cgtmo::sequence;

TEST(Temporal, ZeroTauIsIdentity) {
  const std::vector<double> v{1, 2, 4, 0.5};
  EXPECT_EQ(smooth_in_stops(v, 0), v);
}

TEST(Temporal, ConstantStaysConstant) {
  const std::vector<double> v(20, 3.5);
  for (double x : smooth_in_stops(v, 4)) EXPECT_NEAR(x, 3.5, 1e-12);
}

TEST(Temporal, ThreeFrameWeightsByHand) {
  // tau = 1, middle frame: weights e^-0.5, 1, e^-0.5 over log2 values 0, 2, 0.
  const std::vector<double> v{1, 4, 1};
  const double w = std::exp(-0.5);
  EXPECT_NEAR(smooth_in_stops(v, 1)[1], std::exp2(2.0 / (1 + 2 * w)), 1e-12);
  // First frame: only frames 0..2 exist: weights 1, e^-0.5, e^-2.
  const double w2 = std::exp(-2.0);
  EXPECT_NEAR(smooth_in_stops(v, 1)[0], std::exp2((2 * w) / (1 + w + w2)), 1e-12);
}

TEST(Temporal, AlternatingFlickerIsDamped) {
  std::vector<double> v;
  for (int i = 0; i < 40; ++i) v.push_back(i % 2 ? 2.0 : 1.0);  // one stop of flicker every frame
  EXPECT_NEAR(mean_abs_step_stops(v), 1.0, 1e-12);
  EXPECT_LT(mean_abs_step_stops(smooth_in_stops(v, 3)), 0.01);
}

TEST(Temporal, UnusableValuesAreReplaced) {
  const std::vector<double> v{2, NAN, 2, 0, 2};
  for (double x : smooth_in_stops(v, 1)) EXPECT_NEAR(x, 2, 1e-12);
}
