// Reinhard family against values worked out by hand (Reinhard et al. 2002, Eq. 3 and 4).
#include <gtest/gtest.h>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

TEST(Reinhard, SimpleCurveAtHandPoints) {
  EXPECT_FLOAT_EQ(grey("reinhard", 1.0), 0.5f);   // 1 / 2
  EXPECT_FLOAT_EQ(grey("reinhard", 3.0), 0.75f);  // 3 / 4
  EXPECT_FLOAT_EQ(grey("reinhard", 0.25), 0.2f);  // 0.25 / 1.25
  EXPECT_EQ(grey("reinhard", 0.0), 0.0);
}

TEST(Reinhard, PerChannelByDefault) {
  const RGB out = run1("reinhard", {1.f, 3.f, 0.f});
  EXPECT_FLOAT_EQ(out[0], 0.5f);
  EXPECT_FLOAT_EQ(out[1], 0.75f);
  EXPECT_EQ(out[2], 0.f);
}

TEST(Reinhard, MaxRgbModeScalesByTheMaximum) {
  // max = 2 -> 2/3, every channel scaled by (2/3)/2 = 1/3.
  const RGB out = run1("reinhard", {2.f, 1.f, 0.5f}, {{"mode", "max-rgb"}});
  EXPECT_NEAR(out[0], 2.0 / 3.0, 1e-6);
  EXPECT_NEAR(out[1], 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(out[2], 0.5 / 3.0, 1e-6);
}

TEST(ReinhardExtended, HandValuesWithGivenWhite) {
  // white 4: x (1 + x/16) / (1 + x).
  EXPECT_FLOAT_EQ(grey("reinhard-ext", 2.0, {{"white", "4"}}), 0.75f);   // 2 * 1.125 / 3
  EXPECT_FLOAT_EQ(grey("reinhard-ext", 1.0, {{"white", "4"}}), 0.53125f);  // 1.0625 / 2
}

TEST(ReinhardExtended, WhiteMapsToOne) {
  for (double w : {0.5, 1.0, 3.0, 7.0, 11.2, 100.0, 65504.0}) {
    const std::string ws = std::to_string(w);
    EXPECT_NEAR(grey("reinhard-ext", w, {{"white", ws}}), 1.0, 1e-6) << "white " << w;
    EXPECT_LT(grey("reinhard-ext", 0.99 * w, {{"white", ws}}), 1.0) << "white " << w;
  }
}

TEST(ReinhardExtended, WhiteDefaultsToTheImageMaximumChannel) {
  // Largest channel of the image is 2 (a red channel): white = 2.
  const auto out = run("reinhard-ext", {{2.f, 0.1f, 0.1f}, {0.5f, 0.5f, 0.5f}});
  EXPECT_NEAR(out[0][0], 1.0, 1e-6);
  EXPECT_NEAR(out[1][0], 0.5 * (1 + 0.5 / 4) / 1.5, 1e-6);  // 0.375
}

TEST(ReinhardLuminance, ColourScaledByLoutOverLin) {
  const RGB c = {2.f, 1.f, 0.5f};
  const double lin = 0.2126 * 2 + 0.7152 * 1 + 0.0722 * 0.5;  // 1.1765
  const double ratio = (1 + lin / 16) / (1 + lin);             // Lout / Lin, white 4
  const RGB out = run1("reinhard-lum", c, {{"white", "4"}});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], c[k] * ratio, 1e-6) << k;
}

TEST(ReinhardLuminance, WhiteDefaultsToTheImageMaximumLuminance) {
  // The grey 5 pixel has the largest luminance: it maps to exactly 1.
  const auto out = run("reinhard-lum", {{5.f, 5.f, 5.f}, {0.f, 1.f, 0.f}});
  EXPECT_NEAR(out[0][0], 1.0, 1e-6);
  const double l = 0.7152;
  EXPECT_NEAR(out[1][1], (1 + l / 25) / (1 + l), 1e-6);  // green channel = Lout / Lin * 1
}

TEST(ReinhardLuminance, SaturationZeroGivesGrey) {
  const RGB out = run1("reinhard-lum", {0.5f, 0.2f, 0.1f}, {{"white", "4"}, {"saturation", "0"}});
  const double l = 0.2126 * 0.5 + 0.7152 * 0.2 + 0.0722 * 0.1;
  const double lout = l * (1 + l / 16) / (1 + l);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], lout, 1e-6) << k;
}

TEST(ReinhardJodie, HandValues) {
  // Greys: both terms are x / (1 + x).
  EXPECT_FLOAT_EQ(grey("reinhard-jodie", 1.0), 0.5f);
  // Pure red 1: L = 0.2126, C/(1+L) = 1/1.2126, C/(1+C) = 0.5; lerp(a, b, 0.5) = (a + b) / 2.
  const RGB out = run1("reinhard-jodie", {1.f, 0.f, 0.f});
  EXPECT_NEAR(out[0], (1 / 1.2126 + 0.5) / 2, 1e-6);
  EXPECT_EQ(out[1], 0.f);
  EXPECT_EQ(out[2], 0.f);
}

}  // namespace
}  // namespace cgtmo::operators::test
