// Lottes: the two points the curve is solved through, and its form x^a / (x^(a d) b + c) checked
// by fitting b and c back from two outputs.
#include <gtest/gtest.h>

#include <cmath>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

TEST(Lottes, MidInMapsToMidOutAndHdrMaxToOne) {
  EXPECT_NEAR(grey("lottes", 0.18), 0.267, 1e-6);
  EXPECT_NEAR(grey("lottes", 8.0), 1.0, 1e-6);
  const Params p = {{"mid_in", "0.25"}, {"mid_out", "0.3"}, {"hdr_max", "64"}, {"contrast", "1.3"}, {"shoulder", "0.9"}};
  EXPECT_NEAR(grey("lottes", 0.25, p), 0.3, 1e-6);
  EXPECT_NEAR(grey("lottes", 64.0, p), 1.0, 1e-6);
}

TEST(Lottes, HasThePublishedForm) {
  // y = x^a / (x^(ad) b + c)  <=>  x^a / y = b x^(ad) + c: linear in x^(ad). Three points on
  // that line must be collinear.
  const double a = 1.6, ad = 1.6 * 0.977;
  const double xs[] = {0.05, 0.7, 3.0};
  double u[3], v[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = std::pow(xs[i], ad);
    v[i] = std::pow(xs[i], a) / grey("lottes", xs[i]);
  }
  const double slope01 = (v[1] - v[0]) / (u[1] - u[0]), slope12 = (v[2] - v[1]) / (u[2] - u[1]);
  EXPECT_NEAR(slope01, slope12, 1e-4 * std::abs(slope12));
  EXPECT_EQ(grey("lottes", 0.0), 0.0);
}

TEST(Lottes, ClipsAboveHdrMax) {
  EXPECT_EQ(grey("lottes", 100.0), 1.0);  // d < 1: the curve keeps rising past 1
}

TEST(Lottes, HighContrastDoesNotOverflow) {
  // x^10 overflows float at 65504 (inf / inf was NaN, clamped to black). The curve still passes
  // through its two points and stays at 1 above hdr_max.
  const Params p = {{"contrast", "10"}};
  EXPECT_NEAR(grey("lottes", 0.18, p), 0.267, 1e-5);
  EXPECT_NEAR(grey("lottes", 8.0, p), 1.0, 1e-5);
  EXPECT_EQ(grey("lottes", 65504.0, p), 1.0);
  EXPECT_EQ(grey("lottes", 1000.0, p), 1.0);
}

}  // namespace
}  // namespace cgtmo::operators::test
