// The two ACES fits. Hill: the published matrices written out here, multiplied column by column
// (a different arrangement from the library's rows), around the published rational fit.
// Narkowicz: hand values at chosen points.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

using V3 = std::array<double, 3>;
using M3 = std::array<V3, 3>;  // rows, as published

const M3 kHillIn = {{{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}}};
const M3 kHillOut = {{{1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}}};

// m * v as a sum of the columns weighted by v's components.
V3 mul_by_columns(const M3& m, const V3& v) {
  V3 out = {0, 0, 0};
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) out[row] += m[row][col] * v[col];
  return out;
}

double hill_fit(double v) {
  return (v * v + 0.0245786 * v - 0.000090537) / (0.983729 * v * v + 0.4329510 * v + 0.238081);
}

V3 hill_reference(const V3& c) {
  V3 v = mul_by_columns(kHillIn, c);
  for (double& x : v) x = hill_fit(x);
  v = mul_by_columns(kHillOut, v);
  for (double& x : v) x = std::min(1.0, std::max(0.0, x));
  return v;
}

TEST(AcesHill, MatchesMatricesAroundTheFit) {
  const V3 colours[] = {{0.18, 0.18, 0.18}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                        {0.5, 0.25, 0.1}, {4, 2, 1}, {0.02, 0.3, 0.9}, {10, 10, 10}};
  for (const V3& c : colours) {
    const RGB out = run1("aces-hill", {float(c[0]), float(c[1]), float(c[2])});
    const V3 ref = hill_reference(c);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], ref[k], 2e-6) << c[0] << "," << c[1] << "," << c[2] << " ch " << k;
  }
}

TEST(AcesHill, GreysStayGrey) {
  // Both matrices' rows sum to 1, so a grey goes through the fit alone.
  const RGB out = run1("aces-hill", {0.18f, 0.18f, 0.18f});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], hill_fit(0.18), 2e-5);
  EXPECT_NEAR(hill_fit(0.18), 0.10559, 1e-4);  // by hand: 0.0367336 / 0.347885
}

TEST(AcesHill, NotTheGuidesDefectiveProduct) {
  // The guide's mul read v[1] for v[0] on rows two and three; for pure red that drops the red
  // contribution to G and B. The operator must differ from that clearly.
  auto defective = [](const M3& m, const V3& v) {
    return V3{m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[1] + m[1][1] * v[1] + m[1][2] * v[2],
              m[2][0] * v[1] + m[2][1] * v[1] + m[2][2] * v[2]};
  };
  const V3 red = {1, 0, 0};
  V3 v = defective(kHillIn, red);
  for (double& x : v) x = hill_fit(x);
  v = defective(kHillOut, v);
  const RGB out = run1("aces-hill", {1.f, 0.f, 0.f});
  const V3 ref = hill_reference(red);
  double diff = 0;
  for (int k = 0; k < 3; ++k) diff += std::abs(std::min(1.0, std::max(0.0, v[k])) - ref[k]);
  EXPECT_GT(diff, 0.01);  // the two products differ far beyond the tolerance below
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], ref[k], 2e-6);
}

TEST(AcesNarkowicz, HandValues) {
  // scale 0.6 (the guide's aces_approx), x = 1: 0.6 (1.506 + 0.03) / (0.6 (1.458 + 0.59) + 0.14)
  EXPECT_NEAR(grey("aces-narkowicz", 1.0, {{"scale", "0.6"}}), 0.9216 / 1.3688, 1e-6);
  // scale 1, x = 0.18: 0.18 * 0.4818 / (0.18 * 1.0274 + 0.14)
  EXPECT_NEAR(grey("aces-narkowicz", 0.18), 0.086724 / 0.324932, 1e-6);
  EXPECT_EQ(grey("aces-narkowicz", 0.0), 0.0);
  EXPECT_EQ(grey("aces-narkowicz", 100.0), 1.0);  // 2.51 / 2.43 > 1: clamped
}

TEST(AcesNarkowicz, ScaleIsAnInputMultiplier) {
  EXPECT_NEAR(grey("aces-narkowicz", 0.5, {{"scale", "2"}}), grey("aces-narkowicz", 1.0), 1e-7);
}

}  // namespace
}  // namespace cgtmo::operators::test
