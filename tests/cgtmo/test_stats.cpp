// Scene statistics (src/cgtmo/cgtmo/stats.cpp) against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/cgtmo/stats.h"
#include "scene_builder.h"

using namespace cgtmo::local;
using cgtmo::local::test::plane_scene;

namespace {

std::vector<float> lum_of(const SceneData& s) {
  std::vector<float> l(s.pixel_count());
  for (std::size_t i = 0; i < l.size(); ++i) l[i] = s.rgb[3 * i];  // grey scenes: R = G = B = Y
  return l;
}

bool has_warning(const SceneStats& st, const std::string& part) {
  for (const auto& w : st.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

// 8x4 frame lit by two groups: "lamp" everywhere at 0.5, "hidden" only in column 0 at 0.1
// (so it never wins M) plus the sidecar's emitted luminances.
SceneData two_group_scene() {
  SceneData s = plane_scene(8, 4, [](int x, int) { return x == 3 ? 2.0f : 0.6f; });
  LightGroupPass lamp{"lamp", std::vector<float>(32, 0.5f)};
  LightGroupPass hidden{"hidden", std::vector<float>(32, 0.0f)};
  for (int y = 0; y < 4; ++y) hidden.luminance[y * 8] = 0.1f;
  s.light_groups = {lamp, hidden};
  s.has_sidecar = true;
  s.lights = {{"lamp", "AREA", "lamp", 40.0}, {"hidden", "POINT", "hidden", 900.0}};
  return s;
}

}  // namespace

TEST(SceneStats, LwMaxIsTheBrightestLightInM) {
  const SceneData s = two_group_scene();
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_TRUE(st.light_analysis);
  EXPECT_DOUBLE_EQ(st.lw_max, 40.0);  // 'hidden' (900) never contributes most
  EXPECT_DOUBLE_EQ(st.image_max, 2.0);
  ASSERT_EQ(st.groups.size(), 2u);
  EXPECT_EQ(st.groups[0].pixels_in_m, 32u);
  EXPECT_EQ(st.groups[1].pixels_in_m, 0u);
}

TEST(SceneStats, AGroupThatWinsOnePixelCounts) {
  SceneData s = two_group_scene();
  s.light_groups[1].luminance[5] = 0.7f;  // beats the lamp's 0.5 at one pixel
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 900.0);
  EXPECT_EQ(st.groups[1].pixels_in_m, 1u);
}

TEST(SceneStats, MissingSidecarLuminanceIsMeasuredFromThePass) {
  SceneData s = two_group_scene();
  s.lights[0].luminance = std::nan("");
  s.light_groups[0].luminance[7] = 3.5f;
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 3.5);
  EXPECT_TRUE(has_warning(st, "'lamp'"));
}

TEST(SceneStats, OneLightSkipsTheAnalysis) {
  SceneData s = two_group_scene();
  s.lights = {{"sun", "SUN", "sun", 12345.0}, {"world", "WORLD", "world", 0.0}};  // black world
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_FALSE(st.light_analysis);
  EXPECT_DOUBLE_EQ(st.lw_max, 12345.0);
  EXPECT_NE(st.light_analysis_note.find("one"), std::string::npos);
}

TEST(SceneStats, NoLightsFallsBackToTheImageWithAWarning) {
  SceneData s = plane_scene(6, 3, [](int x, int y) { return 0.1f * float(x + y); });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(st.lw_max, 0.7, 1e-6);
  EXPECT_TRUE(has_warning(st, "no sidecar"));
  EXPECT_TRUE(has_warning(st, "image maximum"));
  EXPECT_TRUE(has_warning(st, "no adaptation probe"));
}

TEST(SceneStats, ProbeMeansBySolidAngle) {
  // 4 rows: latitudes 67.5, 22.5, -22.5, -67.5 degrees; weights cos(lat).
  SceneData s = plane_scene(4, 4, [](int, int) { return 1.0f; });
  const float rows[4] = {8.f, 1.f, 1.f, 2.f};
  s.probe = test::probe(8, 4, [&](int y) { return rows[y]; });
  const double wp = std::cos(67.5 * M_PI / 180), we = std::cos(22.5 * M_PI / 180);
  const double W = 2 * wp + 2 * we;
  const double harm = W / (wp / 8 + we / 1 + we / 1 + wp / 2);
  const double loga = std::exp((wp * std::log(8.0) + wp * std::log(2.0)) / W);
  const SceneStats h = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  const SceneStats g = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(h.lw_a, harm, 1e-6);
  EXPECT_NEAR(g.lw_a, loga, 1e-6);
  EXPECT_NEAR(h.probe_log_average, loga, 1e-6);
  EXPECT_NE(h.lw_a_source.find("probe"), std::string::npos);
}

TEST(SceneStats, BlackDirectionsOfTheProbeAreLeftOut) {
  // Rows 0-1 black (a black world); rows 2 and 3 at 2 and 8 sit at -22.5 and -67.5 degrees.
  SceneData s = plane_scene(4, 4, [](int, int) { return 1.0f; });
  const float rows[4] = {0.f, 0.f, 2.f, 8.f};
  s.probe = test::probe(8, 4, [&](int y) { return rows[y]; });
  const double w2 = std::cos(22.5 * M_PI / 180), w3 = std::cos(67.5 * M_PI / 180);
  const SceneStats g = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(g.lw_a, std::exp((w2 * std::log(2.0) + w3 * std::log(8.0)) / (w2 + w3)), 1e-6);
  EXPECT_NEAR(g.probe_dark_fraction, 0.5, 1e-6);
  const SceneStats h = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  EXPECT_NEAR(h.lw_a, (w2 + w3) / (w2 / 2 + w3 / 8), 1e-6);
}

TEST(SceneStats, BlackProbeFallsBackToTheImage) {
  SceneData s = plane_scene(4, 2, [](int x, int) { return x < 2 ? 1.0f : 4.0f; });
  s.probe = test::probe(8, 4, [](int) { return 0.0f; });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  EXPECT_NEAR(st.lw_a, 2.0 / (1.0 + 0.25), 1e-6);  // the image's harmonic mean of {1, 4}
  EXPECT_TRUE(has_warning(st, "all black"));
  const SceneStats lg = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(lg.lw_a, 2.0, 1e-6);
}

TEST(SceneStats, ZeroLuminanceIsFlooredInBothMeans) {
  const float l[4] = {0.f, 0.f, 1.f, 1.f};
  EXPECT_NEAR(harmonic_mean(l, nullptr, 4), 4.0 / (2 / kMeanFloor + 2), 1e-12);
  EXPECT_NEAR(log_average(l, nullptr, 4), std::sqrt(kMeanFloor), 1e-12);
}

TEST(SceneStats, LwMaxBelowLwAIsWarned) {
  SceneData s = plane_scene(4, 2, [](int, int) { return 1.0f; });
  s.has_sidecar = true;
  s.lights = {{"dim", "POINT", "dim", 0.5}};
  s.probe = test::probe(8, 4, [](int) { return 10.0f; });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 0.5);
  EXPECT_NEAR(st.lw_a, 10.0, 1e-6);
  EXPECT_TRUE(has_warning(st, "below Lw_a"));
}
