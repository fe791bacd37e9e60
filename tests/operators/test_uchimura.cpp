// Uchimura (Gran Turismo): the defining properties of the curve, worked out by hand for the default
// parameters P = 1, a = 1, m = 0.22, l = 0.4, c = 1.33, b = 0:
//   l0 = (P - m) l / a = 0.312, S0 = m + l0 = 0.532, S1 = m + a l0 = 0.532, C2 = a P / (P - S1).
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/errors.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

TEST(Uchimura, LinearSectionIsTheIdentityAtDefaults) {
  for (double x : {0.22, 0.3, 0.4, 0.5, 0.53}) EXPECT_NEAR(grey("uchimura", x), x, 1e-6) << x;
}

TEST(Uchimura, LinearSectionSlopeIsTheContrast) {
  // a = 1.2: l0 = 0.78 * 0.4 / 1.2 = 0.26, section [0.22, 0.48), y = 0.22 + 1.2 (x - 0.22).
  const Params p = {{"contrast", "1.2"}};
  EXPECT_NEAR(grey("uchimura", 0.3, p), 0.22 + 1.2 * 0.08, 1e-6);
  EXPECT_NEAR(grey("uchimura", 0.45, p), 0.22 + 1.2 * 0.23, 1e-6);
  const double slope = (grey("uchimura", 0.45, p) - grey("uchimura", 0.3, p)) / 0.15;
  EXPECT_NEAR(slope, 1.2, 1e-5);
}

TEST(Uchimura, ShoulderByHand) {
  const double s1 = 0.532, c2 = 1.0 / (1.0 - s1);
  for (double x : {0.6, 1.0, 2.0, 4.0})
    EXPECT_NEAR(grey("uchimura", x), 1.0 - (1.0 - s1) * std::exp(-c2 * (x - 0.532)), 1e-6) << x;
  EXPECT_NEAR(grey("uchimura", 65504.0), 1.0, 1e-7);  // the asymptote P
  EXPECT_NEAR(grey("uchimura", 1000.0, {{"max_brightness", "0.8"}}), 0.8, 1e-6);
}

TEST(Uchimura, ContinuousWithMatchingSlopeAtTheShoulderStart) {
  const double s0 = 0.532, h = 1e-3;
  const double below = grey("uchimura", s0 - h), at = grey("uchimura", s0), above = grey("uchimura", s0 + h);
  EXPECT_NEAR(at, 0.532, 1e-6);
  EXPECT_NEAR((at - below) / h, 1.0, 1e-3);  // linear side: slope a = 1
  EXPECT_NEAR((above - at) / h, 1.0, 2e-3);  // shoulder side: C2 (P - S1) / P = a
}

TEST(Uchimura, ToeBlendByHand) {
  // x = 0.11 = m / 2: smoothstep weight 0.5, so f = 0.5 (m (x/m)^c + b) + 0.5 x.
  const double toe = 0.22 * std::pow(0.5, 1.33);
  EXPECT_NEAR(grey("uchimura", 0.11), 0.5 * toe + 0.5 * 0.11, 1e-6);
  EXPECT_EQ(grey("uchimura", 0.0), 0.0);
  EXPECT_NEAR(grey("uchimura", 0.0, {{"pedestal", "0.05"}}), 0.05, 1e-7);
}

TEST(Uchimura, LargeBlackTightnessKeepsHighlightsWhite) {
  // (x / m)^c overflows float for c = 10 at 65504; the toe's weight is 0 there, so the shoulder
  // alone decides: 1 (it was NaN, clamped to black).
  EXPECT_NEAR(grey("uchimura", 65504.0, {{"black", "10"}}), 1.0, 1e-6);
  EXPECT_NEAR(grey("uchimura", 65504.0, {{"black", "10"}, {"linear_start", "0.01"}}), 1.0, 1e-6);
  EXPECT_NEAR(grey("uchimura", 0.3, {{"black", "10"}}), 0.3, 1e-6);  // the linear section is unchanged
}

TEST(Uchimura, MaxBrightnessMustExceedLinearStart) {
  // P <= m turns the shoulder into a growing exponential; the operator refuses it when the user
  // gives both. The default m follows P below 1 (0.22 P), so P alone works over its whole range.
  EXPECT_NEAR(grey("uchimura", 1000.0, {{"max_brightness", "0.2"}}), 0.2, 1e-6);
  EXPECT_NEAR(grey("uchimura", 1000.0, {{"max_brightness", "0.1"}}), 0.1, 1e-6);
  // Below m = 0.022 the curve is the toe blended into the identity line, as at the defaults.
  EXPECT_NEAR(grey("uchimura", 0.03, {{"max_brightness", "0.1"}}), grey("uchimura", 0.03, {{"max_brightness", "0.1"}, {"linear_start", "0.022"}}), 1e-7);
  EXPECT_THROW(grey("uchimura", 0.5, {{"max_brightness", "0.2"}, {"linear_start", "0.22"}}), UsageError);
  EXPECT_THROW(grey("uchimura", 0.5, {{"max_brightness", "0.5"}, {"linear_start", "0.5"}}), UsageError);
  EXPECT_NO_THROW(grey("uchimura", 0.5, {{"max_brightness", "0.5"}, {"linear_start", "0.4"}}));
}

}  // namespace
}  // namespace cgtmo::operators::test
