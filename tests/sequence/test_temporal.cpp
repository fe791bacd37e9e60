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

TEST(Temporal, SparseSmoothingEqualsDenseOnAContiguousShot) {
  std::vector<double> v;
  std::vector<long> frames;
  for (int i = 0; i < 60; ++i) {
    v.push_back(i % 7 == 3 ? NAN : std::exp2(std::sin(i * 0.7) * 3));
    frames.push_back(1001 + i);
  }
  for (double tau : {0.0, 0.5, 2.0, 8.0}) {
    const auto dense = smooth_in_stops(v, tau);
    const auto sparse = smooth_in_stops_at(frames, v, frames, tau);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (std::isfinite(v[i]) || tau > 0) EXPECT_EQ(dense[i], sparse[i]) << "frame " << i << " tau " << tau;  // same bits
  }
}

TEST(Temporal, SparseSmoothingTreatsGapsAsMissingFrames) {
  // Frames 0, 1 and 5 of a shot: the dense series with NaN at 2..4 gives the same values.
  const std::vector<long> frames{0, 1, 5};
  const std::vector<double> values{1, 4, 2};
  const std::vector<double> dense = smooth_in_stops({1, 4, NAN, NAN, NAN, 2}, 2);
  const auto sparse = smooth_in_stops_at(frames, values, {0, 1, 3, 5}, 2);
  EXPECT_EQ(sparse[0], dense[0]);
  EXPECT_EQ(sparse[1], dense[1]);
  EXPECT_EQ(sparse[2], dense[3]);
  EXPECT_EQ(sparse[3], dense[5]);
}

TEST(Temporal, SparseSmoothingOfFarApartFramesDoesNotMixThem) {
  const auto s = smooth_in_stops_at({-99999999, 99999999}, {1, 8}, {-99999999, 99999999, 0}, 8);
  EXPECT_EQ(s[0], 1);
  EXPECT_EQ(s[1], 8);
  EXPECT_TRUE(std::isnan(s[2]));  // no frame within 3 sigma
}
