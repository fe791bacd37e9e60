// Unreal (UE4 FilmToneMap) at its defaults: slope 0.88, toe 0.55, shoulder 0.26, black clip 0,
// white clip 0.04. The test rebuilds the curve's anchors independently: the toe's match point is
// found by bisection so that the toe logistic sends 0.18 to 0.18 (the construction's intent), the
// straight line follows from continuity with the toe at its match point, and the shoulder's match
// from the shoulder size. Greys stay grey through AP1 (its rows sum to 1), so the grey response is
// the curve itself.
#include <gtest/gtest.h>

#include <cmath>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

constexpr double kSlope = 0.88, kToe = 0.55, kShoulder = 0.26, kWhiteClip = 0.04;
constexpr double kToeScale = 1.0 - kToe;                   // 1 + black clip - toe
constexpr double kShoulderScale = 1.0 + kWhiteClip - kShoulder;

double toe_logistic(double log_x, double toe_match) {
  return 2 * kToeScale / (1 + std::exp(-2 * kSlope / kToeScale * (log_x - toe_match)));
}

double toe_match() {  // toe_logistic(log10 0.18, m) = 0.18; decreasing in m
  double lo = -3, hi = 3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (toe_logistic(std::log10(0.18), mid) > 0.18 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double shoulder_match() {
  // Straight line y = slope (L + s) meets the toe at its match point, where the toe is at 1 - toe.
  const double straight = (1 - kToe) / kSlope - toe_match();
  return kShoulder / kSlope - straight;
}

TEST(Unreal, AnchorsAreWhereTheHandCalculationPutsThem) {
  EXPECT_NEAR(toe_match(), -0.390277, 1e-5);
  EXPECT_NEAR(shoulder_match(), -0.606186, 1e-5);  // below the toe's: the curve blends toe and shoulder
}

TEST(Unreal, MidGreyMapsToMidGrey) {
  EXPECT_NEAR(grey("unreal", 0.18), 0.18, 1e-5);
}

TEST(Unreal, ToeBelowTheShoulderMatch) {
  for (double x : {0.001, 0.01, 0.05, 0.2})  // log10 x < shoulder match: pure toe
    EXPECT_NEAR(grey("unreal", x), toe_logistic(std::log10(x), toe_match()), 2e-6) << x;
}

TEST(Unreal, ShoulderAboveTheToeMatch) {
  for (double x : {0.5, 1.0, 4.0, 16.0}) {  // log10 x > toe match: pure shoulder
    const double l = std::log10(x);
    const double ref = 1 + kWhiteClip - 2 * kShoulderScale / (1 + std::exp(2 * kSlope / kShoulderScale * (l - shoulder_match())));
    EXPECT_NEAR(grey("unreal", x), std::min(ref, 1.0), 5e-6) << x;  // float log10 and exp
  }
  EXPECT_EQ(grey("unreal", 65504.0), 1.0);
  EXPECT_EQ(grey("unreal", 0.0), 0.0);
}

TEST(Unreal, MonotonicOnGreysAcrossTheBlend) {
  double prev = -1;
  for (double x : log_sweep(0.01, 10, 2000)) {
    const double y = grey("unreal", x);
    EXPECT_GE(y, prev) << x;
    prev = y;
  }
}

}  // namespace
}  // namespace cgtmo::operators::test
