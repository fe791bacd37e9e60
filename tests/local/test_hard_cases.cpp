// Section 7's hard cases: finite output in [0, 1], no crash, and the documented behaviour
// (docs/cgtmo.md, "Hard cases"), for every filter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cgtmo/local/local_drago.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/scene/sanitize.h"
#include "scene_builder.h"

using namespace cgtmo::local;
using cgtmo::local::test::drago_by_hand;
using cgtmo::local::test::plane_scene;

namespace {

// Every filter an operator runs (filters/filter_table.h: cgtmo's choices and wls).
const std::vector<std::string> kFilters = [] {
  std::vector<std::string> v;
  for (const auto& f : cgtmo::filters::filter_table())
    if (*f.used_by) v.emplace_back(f.name);
  return v;
}();

void expect_ok(const SceneData& s, const LocalOptions& o, const std::string& what) {
  LocalResult r;
  ASSERT_NO_THROW(r = tone_map_local(s, o)) << what;
  ASSERT_EQ(r.rgb.size(), s.pixel_count() * 3);
  for (float v : r.rgb) {
    ASSERT_TRUE(std::isfinite(v)) << what;
    ASSERT_GE(v, 0.f) << what;
    ASSERT_LE(v, 1.f) << what;
  }
}

template <class F>
void for_each_filter(const SceneData& s, F&& tweak, const std::string& what) {
  for (const auto& f : kFilters) {
    LocalOptions o;
    o.filter = f;
    tweak(o);
    expect_ok(s, o, what + " / " + f);
  }
}

auto no_tweak = [](LocalOptions&) {};

SceneData textured(int w, int h) {
  return plane_scene(w, h, [](int x, int y) { return 0.02f + 0.3f * float((x * 13 + y * 7) % 11) / 11.f; });
}

}  // namespace

TEST(HardCases, ZeroNanInfLuminanceAfterTheSanitisePolicy) {
  SceneData s = textured(30, 20);
  const float inf = std::numeric_limits<float>::infinity();
  s.rgb[0] = std::nanf("");
  s.rgb[3 * 5 + 1] = inf;
  s.rgb[3 * 6 + 2] = -inf;
  for (int c = 0; c < 3; ++c) s.rgb[3 * 40 + c] = 0.f;
  const auto rep = cgtmo::scene::sanitize(s.rgb.data(), s.pixel_count(), 3);
  EXPECT_EQ(rep.nan + rep.pos_inf + rep.neg_inf, 3u);
  for_each_filter(s, no_tweak, "sanitised");
  LocalOptions o;
  o.filter = "exact";
  o.lw_max = 100, o.lw_a = 0.1;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_EQ(r.rgb[3 * 40], 0.f);  // black stays black
  EXPECT_EQ(r.rgb[3 * 5 + 1], 1.f);  // +Inf became 65504: far above Lw_max, clipped to white
}

TEST(HardCases, NonFiniteBeautyStraightIntoTheLibrary) {
  // Without the sanitise step: a non-finite luminance counts as 0 and outputs black.
  SceneData s = textured(30, 20);
  s.rgb[3 * 7] = std::nanf("");
  s.rgb[3 * 8 + 1] = std::numeric_limits<float>::infinity();
  for_each_filter(s, no_tweak, "raw non-finite");
  LocalOptions o;
  o.filter = "fast";
  const LocalResult r = tone_map_local(s, o);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(r.rgb[3 * 8 + c], 0.f);
}

TEST(HardCases, BackgroundOnly) {
  SceneData s = textured(20, 10);
  std::fill(s.depth.begin(), s.depth.end(), 1e10f);
  std::fill(s.position.begin(), s.position.end(), 0.f);
  for_each_filter(s, no_tweak, "all background");
  LocalOptions o;
  o.filter = "fast";
  o.lw_max = 5, o.lw_a = 0.2;
  const LocalResult r = tone_map_local(s, o);
  for (std::size_t i = 0; i < s.pixel_count(); ++i)
    ASSERT_NEAR(r.rgb[3 * i], drago_by_hand(s.rgb[3 * i], 5, 0.2), 2e-5);  // global everywhere
}

TEST(HardCases, ZeroLengthAndUnnormalisedNormals) {
  SceneData s = textured(24, 16);
  SceneData scaled = s;
  for (std::size_t i = 0; i < s.pixel_count(); ++i)
    for (int k = 0; k < 3; ++k) scaled.normal[3 * i + k] *= 0.2f;  // Blender's silhouette lengths
  for (const auto& f : {"exact", "fast"}) {
    LocalOptions o;
    o.filter = f;
    o.model_guide = false;
    const LocalResult a = tone_map_local(s, o), b = tone_map_local(scaled, o);
    for (std::size_t i = 0; i < a.rgb.size(); ++i) ASSERT_NEAR(a.rgb[i], b.rgb[i], 1e-6) << f;  // renormalised
  }
  SceneData zero = s;
  for (int k = 0; k < 3; ++k) zero.normal[3 * 50 + k] = 0.f;
  for (int k = 0; k < 3; ++k) zero.normal[3 * 51 + k] = std::nanf("");
  for_each_filter(zero, [](LocalOptions& o) { o.model_guide = false; }, "zero normal");
  LocalOptions o;
  o.filter = "exact";
  o.model_guide = false;
  o.lw_max = 10, o.lw_a = 0.1;
  const LocalResult r = tone_map_local(zero, o);
  EXPECT_EQ(r.explain.invalid_normals, 2u);
  EXPECT_NEAR(r.rgb[3 * 50], std::min(1.0, drago_by_hand(zero.rgb[3 * 50], 10, 0.1)), 2e-5);  // global there
}

TEST(HardCases, ZeroAlbedo) {
  SceneData s = textured(24, 16);
  for (std::size_t i = 0; i < s.pixel_count() / 2; ++i)
    for (int k = 0; k < 3; ++k) s.albedo[3 * i + k] = 0.f;
  for_each_filter(s, no_tweak, "zero albedo");
  std::fill(s.albedo.begin(), s.albedo.end(), 0.f);
  for_each_filter(s, no_tweak, "all albedo zero");
}

TEST(HardCases, LwMaxBelowLwA) {
  const SceneData s = textured(24, 16);
  for_each_filter(s, [](LocalOptions& o) { o.lw_max = 0.01, o.lw_a = 5.0; }, "lw_max < lw_a");
}

TEST(HardCases, AllBlackProbe) {
  SceneData s = textured(24, 16);
  s.probe = test::probe(64, 32, [](int) { return 0.f; });
  for_each_filter(s, no_tweak, "black probe");
  LocalOptions o;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_NE(r.explain.stats.lw_a_source.find("image"), std::string::npos);
}

TEST(HardCases, OneLightAndNoLights) {
  SceneData s = textured(24, 16);
  s.has_sidecar = true;
  s.lights = {{"key", "AREA", "key", 25.0}};
  s.light_groups = {{"key", std::vector<float>(s.pixel_count(), 0.1f)}};
  for_each_filter(s, no_tweak, "one light");
  EXPECT_FALSE(tone_map_local(s, LocalOptions{}).explain.stats.light_analysis);
  // Emission only: no lamps in the sidecar, no light groups: the image maximum, warned.
  s.lights.clear();
  s.light_groups.clear();
  for_each_filter(s, no_tweak, "no lights");
  const LocalResult r = tone_map_local(s, LocalOptions{});
  EXPECT_EQ(r.explain.stats.lw_max_source, "image maximum");
  EXPECT_FALSE(r.explain.stats.warnings.empty());
}

TEST(HardCases, OnePixel) {
  const SceneData s = plane_scene(1, 1, [](int, int) { return 0.5f; });
  for_each_filter(s, no_tweak, "1x1");
  LocalOptions o;
  o.lw_max = 4, o.lw_a = 0.25;
  EXPECT_NEAR(tone_map_local(s, o).rgb[0], drago_by_hand(0.5, 4, 0.25), 2e-5);
  SceneData black = plane_scene(1, 1, [](int, int) { return 0.f; });
  for_each_filter(black, no_tweak, "1x1 black");
}

TEST(HardCases, NarrowerThanTheFilterWindow) {
  // sigma_s 8 px: the window is 49 px wide; these frames are 1-5 px across.
  for_each_filter(textured(5, 60), no_tweak, "5x60");
  for_each_filter(textured(60, 3), no_tweak, "60x3");
  for_each_filter(textured(1, 17), no_tweak, "1x17");
}

TEST(HardCases, NoGBufferAtAll) {
  SceneData s = textured(20, 12);
  s.position.clear();
  s.normal.clear();
  s.albedo.clear();
  s.depth.clear();
  for_each_filter(s, no_tweak, "beauty only");
}
