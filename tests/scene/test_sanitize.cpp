// The one non-finite / out-of-range policy (scene/sanitize.h), value by value, with its counts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cgtmo/scene/sanitize.h"

namespace cgtmo::scene {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenorm = std::numeric_limits<float>::denorm_min();

TEST(Sanitize, PolicyValueByValue) {
  std::vector<float> px = {kNaN, kInf, -kInf,   // -> 0, 65504, 0
                           -2.f, 1e30f, 70000.f,  // -> 0, 65504, 65504
                           65504.f, 0.f, -0.f,    // kept
                           kDenorm, 1e-40f, 1.5f};  // kept (denormals are valid input)
  const SanitizeReport r = sanitize(px.data(), 4, 3);
  const std::vector<float> expected = {0.f, 65504.f, 0.f, 0.f, 65504.f, 65504.f, 65504.f, 0.f, -0.f, kDenorm, 1e-40f, 1.5f};
  for (std::size_t i = 0; i < px.size(); ++i) EXPECT_EQ(px[i], expected[i]) << i;
  EXPECT_EQ(r.nan, 1u);
  EXPECT_EQ(r.pos_inf, 1u);
  EXPECT_EQ(r.neg_inf, 1u);
  EXPECT_EQ(r.negative, 1u);
  EXPECT_EQ(r.over_max, 2u);
  EXPECT_EQ(r.alpha, 0u);
  EXPECT_EQ(r.total(), 6u);
  EXPECT_EQ(r.describe(), "1 NaN set to 0, 1 +Inf set to 65504, 1 -Inf set to 0, 1 negative set to 0, 2 above 65504 clamped");
}

TEST(Sanitize, CleanImageReportsNothing) {
  std::vector<float> px = {0.f, 0.5f, 65504.f, 1e-3f, 2.f, 3.f};
  const std::vector<float> before = px;
  const SanitizeReport r = sanitize(px.data(), 2, 3);
  EXPECT_EQ(px, before);
  EXPECT_EQ(r.total(), 0u);
  EXPECT_EQ(r.describe(), "");
}

TEST(Sanitize, AlphaIsRepairedAndCounted) {
  std::vector<float> px = {1.f, 1.f, 1.f, kNaN,   1.f, 1.f, 1.f, -0.5f, 1.f, 1.f, 1.f, 2.f,
                           1.f, 1.f, 1.f, 0.25f, 1.f, 1.f, 1.f, kInf,  1.f, 1.f, 1.f, -kInf};
  const SanitizeReport r = sanitize(px.data(), 6, 4);
  EXPECT_EQ(px[3], 0.f);
  EXPECT_EQ(px[7], 0.f);
  EXPECT_EQ(px[11], 1.f);
  EXPECT_EQ(px[15], 0.25f);
  EXPECT_EQ(px[19], 1.f);
  EXPECT_EQ(px[23], 0.f);
  EXPECT_EQ(r.alpha, 5u);
  EXPECT_EQ(r.total(), 5u);
}

TEST(Sanitize, CountsAddUpAcrossThreads) {
  // 1000 x 1000 RGB with a NaN in every 7th pixel's green and -Inf in every 11th pixel's blue.
  const std::size_t n = 1000 * 1000;
  std::vector<float> px(n * 3, 0.5f);
  std::size_t nans = 0, neg_infs = 0;
  for (std::size_t i = 0; i < n; i += 7, ++nans) px[i * 3 + 1] = kNaN;
  for (std::size_t i = 0; i < n; i += 11, ++neg_infs) px[i * 3 + 2] = -kInf;
  const SanitizeReport r = sanitize(px.data(), n, 3);
  EXPECT_EQ(r.nan, nans);
  EXPECT_EQ(r.neg_inf, neg_infs);
  EXPECT_EQ(r.total(), nans + neg_infs);
  for (float v : px) ASSERT_TRUE(std::isfinite(v) && v >= 0.f && v <= 65504.f);
}

TEST(Sanitize, FrameOverload) {
  Frame f;
  f.width = 2;
  f.height = 1;
  f.channels = 3;
  f.beauty = {kNaN, 1.f, 1.f, 1.f, 1.f, kInf};
  const SanitizeReport r = sanitize(f);
  EXPECT_EQ(r.nan, 1u);
  EXPECT_EQ(r.pos_inf, 1u);
  EXPECT_EQ(f.beauty[0], 0.f);
  EXPECT_EQ(f.beauty[5], 65504.f);
}

}  // namespace
}  // namespace cgtmo::scene
