// The local Drago pipeline (src/cgtmo/cgtmo/local_drago.cpp): the curve against Drago's formula
// written out by hand, the background rule, colour restoration, guide modelling, and every
// filter on the same frames.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cgtmo/cgtmo/local_drago.h"
#include "cgtmo/filters/filter_table.h"
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

LocalOptions with(const std::string& filter, double lw_max = 0, double lw_a = 0) {
  LocalOptions o;
  o.filter = filter;
  o.lw_max = lw_max;
  o.lw_a = lw_a;
  return o;
}

void expect_finite_in_range(const LocalResult& r, const std::string& what) {
  for (float v : r.rgb) {
    ASSERT_TRUE(std::isfinite(v)) << what;
    ASSERT_GE(v, 0.f) << what;
    ASSERT_LE(v, 1.f) << what;
  }
}

bool explain_has(const LocalResult& r, const std::string& part) {
  for (const auto& l : describe(r.explain))
    if (l.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(LocalDrago, FlatFrameIsTheGlobalCurve) {
  // A constant frame is its own base layer under every filter: Ld = TC(L).
  const SceneData s = plane_scene(40, 30, [](int, int) { return 0.3f; });
  for (const auto& f : kFilters) {
    const LocalResult r = tone_map_local(s, with(f, 20.0, 0.1));
    const double expect = drago_by_hand(0.3, 20.0, 0.1);
    for (std::size_t i = 0; i < s.pixel_count(); ++i) ASSERT_NEAR(r.rgb[3 * i], expect, 2e-5) << f;
  }
}

TEST(LocalDrago, DetailRidesOnTheBase) {
  // Ld / TC(base) = L / base at every pixel: the detail layer passes through unchanged.
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.05f, 0.4f);
  std::vector<float> field(48 * 32);
  for (auto& v : field) v = u(rng);
  const SceneData s = plane_scene(48, 32, [&](int x, int y) { return field[y * 48 + x]; });
  for (const auto& f : kFilters) {
    const LocalResult r = tone_map_local(s, with(f, 50.0, 0.2));
    for (std::size_t i = 0; i < s.pixel_count(); ++i) {
      const double base = std::pow(10.0, double(r.base_log[i]));
      const double expect = drago_by_hand(base, 50.0, 0.2) * field[i] / base;
      ASSERT_NEAR(r.rgb[3 * i], std::min(expect, 1.0), 2e-5) << f << " px " << i;
    }
  }
}

TEST(LocalDrago, BackgroundGetsTheGlobalCurveAndStaysOutOfTheForeground) {
  // Left half background (depth 1e10) at two different luminances: the background pixels follow
  // TC(L) exactly and the foreground output does not change.
  auto make = [](float sky) {
    SceneData s = plane_scene(40, 24, [&](int x, int y) { return x < 20 ? sky : 0.05f + 0.01f * float((x * 7 + y * 3) % 5); });
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 20; ++x) s.depth[y * 40 + x] = 1e10f;
    return s;
  };
  const SceneData a = make(30.f), b = make(0.001f);
  for (const auto& f : kFilters) {
    const LocalResult ra = tone_map_local(a, with(f, 100.0, 0.1));
    const LocalResult rb = tone_map_local(b, with(f, 100.0, 0.1));
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 40; ++x) {
        const std::size_t i = std::size_t(y) * 40 + x;
        if (x < 20) {
          EXPECT_NEAR(ra.rgb[3 * i], std::min(1.0, drago_by_hand(30.0, 100.0, 0.1)), 2e-5) << f;
        } else {
          ASSERT_NEAR(ra.rgb[3 * i], rb.rgb[3 * i], 1e-6) << f << " at " << x << "," << y;
        }
      }
    EXPECT_NEAR(ra.explain.background_fraction, 0.5, 1e-12);
  }
}

TEST(LocalDrago, SaturationControlsColour) {
  SceneData s = plane_scene(16, 16, [](int, int) { return 0.2f; });
  for (std::size_t i = 0; i < s.pixel_count(); ++i) {  // a saturated orange of luminance 0.2
    s.rgb[3 * i] = 0.5f;
    s.rgb[3 * i + 1] = (0.2f - 0.2126f * 0.5f - 0.0722f * 0.05f) / 0.7152f;
    s.rgb[3 * i + 2] = 0.05f;
  }
  LocalOptions o = with("exact", 10.0, 0.1);
  const double ld = drago_by_hand(0.2, 10.0, 0.1);
  o.saturation = 1.0;
  LocalResult r = tone_map_local(s, o);
  EXPECT_NEAR(r.rgb[0] / r.rgb[2], 10.0, 1e-3);  // hue ratios kept
  EXPECT_NEAR(r.rgb[0], ld * 0.5 / 0.2, 1e-5);
  o.saturation = 0.0;
  r = tone_map_local(s, o);
  EXPECT_NEAR(r.rgb[0], ld, 1e-5);  // grey at the tone-mapped luminance
  EXPECT_NEAR(r.rgb[1], ld, 1e-5);
  EXPECT_NEAR(r.rgb[2], ld, 1e-5);
  o.saturation = 0.5;
  r = tone_map_local(s, o);
  EXPECT_NEAR(r.rgb[0], ld * std::sqrt(0.5 / 0.2), 1e-5);
}

TEST(LocalDrago, UniformAlbedoAndPlanarSceneDropTheirGroups) {
  // One plane, one albedo: normals and albedo carry nothing; positions do.
  const SceneData s = plane_scene(32, 32, [](int x, int) { return x < 16 ? 0.1f : 1.0f; });
  const LocalResult r = tone_map_local(s, with("exact", 10.0, 0.3));
  EXPECT_EQ(r.explain.guide_available, unsigned(cgtmo::filters::kGuideAll));
  EXPECT_EQ(r.explain.guide_used, unsigned(cgtmo::filters::kGuidePosition));
  EXPECT_TRUE(explain_has(r, "dropped normal+albedo"));
  // With a second albedo the albedo group is kept.
  SceneData t = s;
  for (std::size_t i = 0; i < t.pixel_count(); i += 2) t.albedo[3 * i] = 0.9f;
  EXPECT_TRUE(tone_map_local(t, with("exact", 10.0, 0.3)).explain.guide_used & cgtmo::filters::kGuideAlbedo);
  // guide=all keeps every group.
  LocalOptions all = with("exact", 10.0, 0.3);
  all.model_guide = false;
  EXPECT_EQ(tone_map_local(s, all).explain.guide_used, unsigned(cgtmo::filters::kGuideAll));
}

TEST(LocalDrago, GuideStopsBleedingAcrossAnEdgeOfSimilarLuminance) {
  // Two surfaces (normals 90 degrees apart) whose luminances differ by 0.3 decades, less than
  // the bilateral's range sigma (0.4): the G-buffer filter keeps the left surface's light off the
  // right one; the plain bilateral cannot tell the surfaces apart and bleeds.
  SceneData s = plane_scene(48, 32, [](int x, int) { return x < 24 ? 0.4f : 0.2f; });
  for (int y = 0; y < 32; ++y)
    for (int x = 24; x < 48; ++x) {
      float* n = &s.normal[3 * (std::size_t(y) * 48 + x)];
      n[0] = 1.f, n[1] = 0.f, n[2] = 0.f;
    }
  const LocalResult g = tone_map_local(s, with("exact", 10.0, 0.2));
  const LocalResult b = tone_map_local(s, with("bilateral", 10.0, 0.2));
  const std::size_t i = 16 * 48 + 25;  // right surface, next to the edge
  EXPECT_NEAR(g.base_log[i], std::log10(0.2), 0.01);
  EXPECT_GT(b.base_log[i], std::log10(0.2) + 0.02);
}
