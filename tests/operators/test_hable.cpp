// Hable's curves. Uncharted 2: the published rational formula, rearranged and evaluated in double
// here. Piecewise: the defining properties of the construction in Hable's 2017 post.
#include <gtest/gtest.h>

#include <cmath>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

// (A x^2 + B C x + D E) / (A x^2 + B x + D F) - E / F: the Uncharted 2 curve, expanded.
double uncharted2(double x, double A, double B, double C, double D, double E, double F) {
  return (A * x * x + B * C * x + D * E) / (A * x * x + B * x + D * F) - E / F;
}

double hable_reference(double x) {
  const double k[] = {0.15, 0.50, 0.10, 0.20, 0.02, 0.30};
  return uncharted2(2.0 * x, k[0], k[1], k[2], k[3], k[4], k[5]) /
         uncharted2(11.2, k[0], k[1], k[2], k[3], k[4], k[5]);
}

TEST(Hable, MatchesThePublishedFormula) {
  for (double x : {0.01, 0.1, 0.18, 0.5, 1.0, 2.0, 4.0, 5.5})
    EXPECT_NEAR(grey("hable", x), hable_reference(x), 2e-6) << x;
}

TEST(Hable, WhiteOverExposureBiasMapsToOne) {
  // The white scale is 1 / partial(11.2) and the input is multiplied by 2 first: 5.6 -> 1.
  EXPECT_NEAR(grey("hable", 5.6), 1.0, 2e-6);
  EXPECT_EQ(grey("hable", 20.0), 1.0);  // above: clipped
  EXPECT_NEAR(grey("hable", 0.0), 0.0, 1e-7);
}

TEST(Hable, OtherCoefficients) {
  // Hable's later blog values: A=0.22 B=0.30 C=0.10 D=0.20 E=0.01 F=0.30, bias 1, white 11.2.
  const Params p = {{"A", "0.22"}, {"B", "0.3"}, {"C", "0.1"}, {"D", "0.2"},
                    {"E", "0.01"}, {"F", "0.3"}, {"exposure_bias", "1"}, {"white", "11.2"}};
  for (double x : {0.05, 0.5, 3.0, 9.0}) {
    const double ref = uncharted2(x, 0.22, 0.3, 0.1, 0.2, 0.01, 0.3) / uncharted2(11.2, 0.22, 0.3, 0.1, 0.2, 0.01, 0.3);
    EXPECT_NEAR(grey("hable", x, p), ref, 2e-6) << x;
  }
}

// Defaults: toe strength 0.5, toe length 0.5, shoulder strength 2, shoulder length 0.5, angle 1,
// gamma 1. By hand (Hable's construction): x0 = 0.25, y0 = 0.125, x1 = 0.6875, y1 = 0.5625 in the
// perceptual space, W = 0.25 + 0.875 + (2^2 - 1) = 4.125; the section ends in input units are
// x0^2.2 and x1^2.2 (the 2.2 power maps the perceptual space to linear).
constexpr double kW = 4.125;
const double kX0 = std::pow(0.25, 2.2), kX1 = std::pow(0.6875, 2.2);

TEST(HablePiecewise, WhiteMapsToOneAndBlackToZero) {
  EXPECT_NEAR(grey("hable-piecewise", kW), 1.0, 1e-5);
  EXPECT_LT(grey("hable-piecewise", 0.9 * kW), 1.0);
  EXPECT_EQ(grey("hable-piecewise", 0.0), 0.0);
}

TEST(HablePiecewise, LinearSectionRatioAndStraightness) {
  const double f0 = grey("hable-piecewise", kX0), f1 = grey("hable-piecewise", kX1);
  // With gamma 1 the section joins (x0^2.2, y0^2.2) and (x1^2.2, y1^2.2), up to one common scale.
  EXPECT_NEAR(f1 / f0, std::pow(0.5625 / 0.125, 2.2), 1e-3 * std::pow(4.5, 2.2));
  // Straight in between.
  const double mid = grey("hable-piecewise", 0.5 * (kX0 + kX1));
  EXPECT_NEAR(mid, 0.5 * (f0 + f1), 1e-5);
}

TEST(HablePiecewise, ContinuousWithContinuousSlopeAtTheJoins) {
  for (double x : {kX0, kX1}) {
    const double h = 1e-3 * x;
    const double below = grey("hable-piecewise", x - h), at = grey("hable-piecewise", x),
                 above = grey("hable-piecewise", x + h);
    EXPECT_NEAR(below, at, 5e-3 * at) << x;
    EXPECT_NEAR(above, at, 5e-3 * at) << x;
    const double left_slope = (at - below) / h, right_slope = (above - at) / h;
    EXPECT_NEAR(left_slope, right_slope, 0.02 * right_slope) << x;
  }
}

TEST(HablePiecewise, HableOwnDefaultsGiveTheClippedIdentity) {
  // Hable's own defaults (no toe or shoulder strength, no angle): y0 = x0 and y1 = x1, W = 1; toe,
  // linear section and shoulder all solve to y = x (slope 1 through points on the diagonal).
  const Params p = {{"toe_strength", "0"}, {"shoulder_strength", "0"}, {"shoulder_angle", "0"}};
  for (double x : {0.01, 0.04, 0.1, 0.3, 0.43, 0.7, 0.95}) EXPECT_NEAR(grey("hable-piecewise", x, p), x, 1e-5) << x;
  EXPECT_NEAR(grey("hable-piecewise", 1.0, p), 1.0, 1e-5);
  EXPECT_EQ(grey("hable-piecewise", 3.0, p), 1.0);
}

}  // namespace
}  // namespace cgtmo::operators::test
