// The pipeline (apply.cpp): exposure, image statistics worked out by hand, alpha, and the numerical
// hard cases for every operator and mode, run as the CLI runs them: scene::sanitize, then tonemap.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cgtmo/operators/registry.h"
#include "cgtmo/scene/sanitize.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenorm = std::numeric_limits<float>::denorm_min();

TEST(ImageStats, ByHandOnTwoPixels) {
  const float px[] = {3.f, 0.5f, 0.f, 1.f, 2.f, 1.f};
  const ImageStats s = compute_image_stats(px, 2, 3);
  EXPECT_DOUBLE_EQ(s.max_channel, 3.0);
  const double l1 = 0.2126 * 3 + 0.7152 * 0.5, l2 = 0.2126 + 0.7152 * 2 + 0.0722;  // 0.9954, 1.7152
  EXPECT_NEAR(s.max_luminance, l2, 1e-6);
  EXPECT_NEAR(s.log_average_luminance, std::sqrt((1e-4 + l1) * (1e-4 + l2)), 1e-6);  // geometric mean
}

TEST(ImageStats, LogAverageUsesEpsilon1e4) {
  const float grey_and_black[] = {1.f, 1.f, 1.f, 0.f, 0.f, 0.f};
  EXPECT_NEAR(compute_image_stats(grey_and_black, 2, 3).log_average_luminance, std::sqrt(1.0001e-4), 1e-9);
  const float black[] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f};
  const ImageStats s = compute_image_stats(black, 3, 3);
  EXPECT_NEAR(s.log_average_luminance, 1e-4, 1e-15);
  EXPECT_EQ(s.max_channel, 0.0);
  EXPECT_EQ(s.max_luminance, 0.0);
  EXPECT_NEAR(compute_image_stats(nullptr, 0, 3).log_average_luminance, 1e-4, 1e-15);
}

TEST(ImageStats, LargeImageAcrossThreadsAndAlphaIgnored) {
  // 1000 x 1000 RGBA: half the pixels grey 1, half black, one pixel (0, 8, 0); alpha 50 everywhere.
  const std::size_t n = 1000 * 1000;
  std::vector<float> px(n * 4, 0.f);
  for (std::size_t i = 0; i < n; ++i) {
    const float v = (i % 2) ? 1.f : 0.f;
    px[i * 4 + 0] = px[i * 4 + 1] = px[i * 4 + 2] = v;
    px[i * 4 + 3] = 50.f;
  }
  px[500123 * 4 + 0] = 0.f;  // an odd index: was grey 1
  px[500123 * 4 + 1] = 8.f;
  px[500123 * 4 + 2] = 0.f;
  const ImageStats s = compute_image_stats(px.data(), n, 4);
  EXPECT_DOUBLE_EQ(s.max_channel, 8.0);
  EXPECT_NEAR(s.max_luminance, 8 * 0.7152, 1e-5);
  const double expected_log = ((n / 2 - 1) * std::log(1.0001) + (n / 2) * std::log(1e-4) + std::log(1e-4 + 8 * 0.7152)) / n;
  EXPECT_NEAR(s.log_average_luminance, std::exp(expected_log), 1e-9);
}

TEST(ToneMap, ExposureComesBeforeTheStatistics) {
  // reinhard-ext's white defaults to the largest channel after exposure: 2 at +1 EV.
  std::vector<RGB> px = {{1.f, 0.5f, 0.25f}};
  ToneMapRequest req;
  req.op = "reinhard-ext";
  req.exposure_ev = 1.0;
  const ToneMapResult r = tonemap(px[0].data(), 1, 3, req);
  EXPECT_TRUE(r.used_image_stats);
  EXPECT_DOUBLE_EQ(r.stats.max_channel, 2.0);
  EXPECT_DOUBLE_EQ(r.params.number("white"), 2.0);
  EXPECT_NEAR(px[0][0], 1.0, 1e-6);
  EXPECT_NEAR(px[0][1], 1.0 * (1 + 1.0 / 4) / 2, 1e-6);  // 1 after exposure, white 2
  EXPECT_EQ(r.kind, Kind::PerChannel);
}

TEST(ToneMap, ExposureSaturatesAtTheHalfMaximum) {
  std::vector<RGB> px = {{40000.f, 1.f, 0.f}};
  ToneMapRequest req;
  req.op = "reinhard-ext";
  req.exposure_ev = 3.0;
  const ToneMapResult r = tonemap(px[0].data(), 1, 3, req);
  EXPECT_DOUBLE_EQ(r.stats.max_channel, 65504.0);
}

TEST(ToneMap, NoStatisticsWhenNoParameterNeedsThem) {
  std::vector<RGB> px = {{1.f, 1.f, 1.f}};
  ToneMapRequest req;
  req.op = "hable";
  EXPECT_FALSE(tonemap(px[0].data(), 1, 3, req).used_image_stats);
  req.op = "reinhard-ext";
  req.params = {{"white", "4"}};
  EXPECT_FALSE(tonemap(px[0].data(), 1, 3, req).used_image_stats);
}

TEST(ToneMap, AlphaPassesThrough) {
  for (const auto& op : operators_of(Scope::Pixel)) {
    float px[] = {0.5f, 0.2f, 0.1f, 0.3f, 4.f, 4.f, 4.f, 1.f, 0.f, 0.f, 0.f, 0.f};
    ToneMapRequest req;
    req.op = op.name;
    tonemap(px, 3, 4, req);
    EXPECT_EQ(px[3], 0.3f) << op.name;
    EXPECT_EQ(px[7], 1.f) << op.name;
    EXPECT_EQ(px[11], 0.f) << op.name;
  }
}

// The hard cases: every special value, alone and mixed, plus pure primaries with tiny luminance.
// Counted by hand for the sanitize report (per channel):
//   NaN 3, +Inf 3, -Inf 2, negative finite 4, above 65504 finite 3.
std::vector<RGB> hard_pixels() {
  const float big = 1e30f, fmax = std::numeric_limits<float>::max();
  return {
      {0.f, 0.f, 0.f},
      {-1.f, -0.f, -1e-30f},          // 2 negative (-0 is not negative)
      {kNaN, 1.f, 0.5f},              // 1 NaN
      {kInf, 0.f, 0.f},               // 1 +Inf
      {-kInf, 65504.f, kDenorm},      // 1 -Inf
      {1e-40f, kDenorm, 1e-45f},      // denormals
      {65504.f, 65504.f, 65504.f},
      {big, big, fmax},               // 3 above 65504
      {kDenorm, 0.f, 0.f},            // primaries with tiny luminance
      {0.f, kDenorm, 0.f},
      {0.f, 0.f, kDenorm},
      {1e-30f, 0.f, 0.f},
      {0.f, 1e-38f, 0.f},
      {0.f, 0.f, 1e-20f},
      {kNaN, kNaN, kInf},             // 2 NaN, 1 +Inf
      {-kInf, -65504.f, -1e30f},      // 1 -Inf, 2 negative
      {kInf, 1e-40f, 65504.f},        // 1 +Inf
      {1.f, 0.f, 0.f},                // pure primaries
      {0.f, 1.f, 0.f},
      {0.f, 0.f, 1.f},
      {65504.f, 0.f, 0.f},
      {0.f, 0.f, 65504.f},
  };
}

std::vector<std::string> modes_of(const OperatorDef& op) {
  for (const auto& p : op.params)
    if (p.name == "mode") return p.choices;
  return {""};
}

void expect_in_range(const std::vector<RGB>& px, const std::string& what) {
  for (std::size_t i = 0; i < px.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(std::isfinite(px[i][k]) && px[i][k] >= 0.f && px[i][k] <= 1.f)
          << what << ": pixel " << i << " channel " << k << " = " << px[i][k];
}

// sanitize then tonemap, as the CLI does; returns the sanitize report.
scene::SanitizeReport pipeline(std::vector<RGB>& px, const std::string& op, const std::string& mode, double ev) {
  const scene::SanitizeReport rep = scene::sanitize(px.empty() ? nullptr : px[0].data(), px.size(), 3);
  ToneMapRequest req;
  req.op = op;
  if (!mode.empty()) req.params = {{"mode", mode}};
  req.exposure_ev = ev;
  tonemap(px.empty() ? nullptr : px[0].data(), px.size(), 3, req);
  return rep;
}

TEST(HardCases, EveryOperatorEveryModeGivesFiniteOutputInRange) {
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op))
      for (double ev : {0.0, 30.0, 64.0, -30.0, -64.0}) {  // the CLI allows [-64, 64]
        const std::string what = op.name + (mode.empty() ? "" : " mode=" + mode) + " ev=" + std::to_string(ev);
        // The whole set as one 1xN image.
        std::vector<RGB> px = hard_pixels();
        const auto rep = pipeline(px, op.name, mode, ev);
        EXPECT_EQ(rep.nan, 3u);
        EXPECT_EQ(rep.pos_inf, 3u);
        EXPECT_EQ(rep.neg_inf, 2u);
        EXPECT_EQ(rep.negative, 4u);
        EXPECT_EQ(rep.over_max, 3u);
        EXPECT_EQ(rep.alpha, 0u);
        expect_in_range(px, what + " (1xN)");
        // Every pixel alone as a 1x1 image: image statistics come from that pixel only.
        for (const RGB& c : hard_pixels()) {
          std::vector<RGB> one = {c};
          pipeline(one, op.name, mode, ev);
          expect_in_range(one, what + " (1x1 " + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," +
                                   std::to_string(c[2]) + ")");
        }
      }
}

TEST(HardCases, AllBlackImages) {
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op))
      for (std::size_t n : {1u, 7u, 4096u}) {
        std::vector<RGB> px(n, RGB{0.f, 0.f, 0.f});
        const auto rep = pipeline(px, op.name, mode, 0.0);
        EXPECT_EQ(rep.total(), 0u);
        expect_in_range(px, op.name + " " + mode + " black");
        // Black stays black, except where the operator lifts it on purpose (none at defaults).
        for (const RGB& c : px) EXPECT_EQ(c, (RGB{0.f, 0.f, 0.f})) << op.name << " " << mode;
      }
}

TEST(HardCases, EmptyImageIsANoOp) {
  for (const auto& op : operators_of(Scope::Pixel)) {
    std::vector<RGB> none;
    EXPECT_NO_THROW(pipeline(none, op.name, "", 0.0)) << op.name;
  }
}

}  // namespace
}  // namespace cgtmo::operators::test
