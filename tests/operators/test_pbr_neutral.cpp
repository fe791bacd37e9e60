// Khronos PBR Neutral against the specification's rules, worked by hand.
#include <gtest/gtest.h>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

TEST(PbrNeutral, ColoursBelowCompressionLoseOnlyTheOffset) {
  // min >= 0.08: offset 0.04 subtracted, peak 0.46 < 0.76: nothing else.
  const RGB out = run1("pbr-neutral", {0.5f, 0.3f, 0.1f});
  EXPECT_NEAR(out[0], 0.46, 1e-6);
  EXPECT_NEAR(out[1], 0.26, 1e-6);
  EXPECT_NEAR(out[2], 0.06, 1e-6);
}

TEST(PbrNeutral, SmallMinimumUsesTheQuadraticOffset) {
  // min 0.05 < 0.08: offset = 0.05 - 6.25 * 0.05^2 = 0.034375.
  const RGB out = run1("pbr-neutral", {0.4f, 0.2f, 0.05f});
  EXPECT_NEAR(out[0], 0.365625, 1e-6);
  EXPECT_NEAR(out[1], 0.165625, 1e-6);
  EXPECT_NEAR(out[2], 0.015625, 1e-6);
  // Greys below 0.08 map to 6.25 x^2, meeting x - 0.04 at 0.08.
  EXPECT_NEAR(grey("pbr-neutral", 0.04), 6.25 * 0.04 * 0.04, 1e-7);
  EXPECT_NEAR(grey("pbr-neutral", 0.08), 0.04, 1e-7);
  EXPECT_EQ(grey("pbr-neutral", 0.0), 0.0);
}

TEST(PbrNeutral, PeakCompression) {
  // Grey 1: after offset 0.96 >= 0.76; d = 0.24, new peak = 1 - 0.0576 / (0.96 + 0.24 - 0.76).
  EXPECT_NEAR(grey("pbr-neutral", 1.0), 1.0 - 0.0576 / 0.44, 1e-6);
  // Grey 0.8 is exactly at the compression start: 0.76 -> 1 - 0.0576 / 0.24 = 0.76, continuous.
  EXPECT_NEAR(grey("pbr-neutral", 0.8), 0.76, 1e-6);
  EXPECT_LT(grey("pbr-neutral", 65504.0), 1.0 + 1e-7);
  EXPECT_GT(grey("pbr-neutral", 65504.0), 0.9999);
}

TEST(PbrNeutral, CompressedColourDesaturatesTowardThePeak) {
  // (2, 1, 0.5): offset 0.04 -> (1.96, 0.96, 0.46), peak 1.96.
  const double peak = 1.96, d = 0.24;
  const double new_peak = 1 - d * d / (peak + d - 0.76);
  const double s = new_peak / peak;
  const double g = 1 - 1 / (0.15 * (peak - new_peak) + 1);
  const double c[3] = {1.96, 0.96, 0.46};
  const RGB out = run1("pbr-neutral", {2.f, 1.f, 0.5f});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], (1 - g) * c[k] * s + g * new_peak, 1e-6) << k;
  EXPECT_NEAR(out[0], new_peak, 1e-6);  // the peak channel lands on the new peak
}

}  // namespace
}  // namespace cgtmo::operators::test
