// The local Drago pipeline (src/cgtmo/local/local_drago.cpp): the curve against Drago's formula
// written out by hand, the background rule, colour restoration, guide modelling, and every
// filter on the same frames.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cgtmo/local/local_drago.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "scene_builder.h"

using namespace cgtmo::local;
namespace scene = cgtmo::scene;
using cgtmo::local::test::drago_by_hand;
using cgtmo::local::test::plane_scene;

namespace {

const std::vector<std::string> kFilters = cgtmo::local::test::operator_filters();

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
  const scene::Frame s = plane_scene(40, 30, [](int, int) { return 0.3f; });
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
  const scene::Frame s = plane_scene(48, 32, [&](int x, int y) { return field[y * 48 + x]; });
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
    scene::Frame s = plane_scene(40, 24, [&](int x, int y) { return x < 20 ? sky : 0.05f + 0.01f * float((x * 7 + y * 3) % 5); });
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 20; ++x) s.depth[y * 40 + x] = 1e10f;
    return s;
  };
  const scene::Frame a = make(30.f), b = make(0.001f);
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
  scene::Frame s = plane_scene(16, 16, [](int, int) { return 0.2f; });
  for (std::size_t i = 0; i < s.pixel_count(); ++i) {  // a saturated orange of luminance 0.2
    s.beauty[3 * i] = 0.5f;
    s.beauty[3 * i + 1] = (0.2f - 0.2126f * 0.5f - 0.0722f * 0.05f) / 0.7152f;
    s.beauty[3 * i + 2] = 0.05f;
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
  const scene::Frame s = plane_scene(32, 32, [](int x, int) { return x < 16 ? 0.1f : 1.0f; });
  const LocalResult r = tone_map_local(s, with("exact", 10.0, 0.3));
  EXPECT_EQ(r.explain.guide_available, unsigned(cgtmo::filters::kGuideAll));
  EXPECT_EQ(r.explain.guide_used, unsigned(cgtmo::filters::kGuidePosition));
  EXPECT_TRUE(explain_has(r, "dropped normal+albedo"));
  // With a second albedo the albedo group is kept.
  scene::Frame t = s;
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
  scene::Frame s = plane_scene(48, 32, [](int x, int) { return x < 24 ? 0.4f : 0.2f; });
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

// output=scene-linear: two flat surfaces (different normals, so the guide keeps them apart) at Lw_a
// and 10 stops above it. With the target 5 stops above Lw_a (stops = 5 + log2(Lw_a / 0.18)) the
// shoulder starts at 3/4 of it, v / (1 + k v) with k = (10 - 5) / (6.25 * 1.25): the dark one stays
// at Lw_a, the bright one comes down to Lw_a * 2^5, unclamped.
TEST(LocalDrago, SceneLinearOutputCompressesTheHighlightsAroundLwA) {
  scene::Frame s = plane_scene(64, 32, [](int x, int) { return x < 32 ? 0.25f : 256.f; });
  for (int y = 0; y < 32; ++y)
    for (int x = 32; x < 64; ++x) {
      float* n = &s.normal[3 * (std::size_t(y) * 64 + x)];
      n[0] = 1.f, n[2] = 0.f;
    }
  LocalOptions o = with("exact", 1000, 0.25);
  o.output = LocalOptions::Output::SceneLinear;
  o.target_stops = 5 + std::log2(0.25 / kSceneLinearGrey);
  o.shadow_stops = 0;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_NEAR(r.explain.base_headroom_stops, 10.0, 1e-3);
  EXPECT_NEAR(r.explain.pre.target, 5.0, 1e-9);
  EXPECT_NEAR(r.explain.pre.k_high, 5.0 / (6.25 * 1.25), 1e-4);
  for (int y = 0; y < 32; ++y) {
    EXPECT_NEAR(r.rgb[3 * (std::size_t(y) * 64 + 2)], 0.25f, 0.0025f);  // Lw_a within 1%
    EXPECT_NEAR(r.rgb[3 * (std::size_t(y) * 64 + 61)], 0.25f * 32.f, 0.08f);
  }
  // A target wider than the range leaves the render as it is.
  o.target_stops = 12;
  const LocalResult same = tone_map_local(s, o);
  EXPECT_EQ(same.explain.pre.k_high, 0.0);
  for (std::size_t i = 0; i < s.beauty.size(); ++i) ASSERT_NEAR(same.rgb[i], s.beauty[i], 1e-5f * s.beauty[i]);
}

// The shadows: a surface 10 stops under Lw_a, with shadows = 3, is lifted by the toe from 1.5
// stops under Lw_a: w = 8.5 -> 8.5 / (1 + 8.5 / 1.5), so it lands 1.5 + 1.275 stops under Lw_a;
// the surface at Lw_a stays.
TEST(LocalDrago, SceneLinearOutputLiftsTheShadowsTowardsLwA) {
  const float lw_a = 0.25f, dark = lw_a / 1024.f;
  scene::Frame s = plane_scene(64, 32, [&](int x, int) { return x < 32 ? lw_a : dark; });
  for (int y = 0; y < 32; ++y)
    for (int x = 32; x < 64; ++x) {
      float* n = &s.normal[3 * (std::size_t(y) * 64 + x)];
      n[0] = 1.f, n[2] = 0.f;
    }
  LocalOptions o = with("exact", 1000, lw_a);
  o.output = LocalOptions::Output::SceneLinear;
  o.shadow_stops = 3;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_EQ(r.explain.pre.k_high, 0.0);
  const double expected = lw_a * std::exp2(-(1.5 + 8.5 / (1 + 8.5 / 1.5)));
  for (int y = 0; y < 32; ++y) {
    EXPECT_NEAR(r.rgb[3 * (std::size_t(y) * 64 + 2)], lw_a, 0.01 * lw_a);
    EXPECT_NEAR(r.rgb[3 * (std::size_t(y) * 64 + 61)], expected, 0.01 * expected);
  }
  o.shadow_stops = 0;
  const LocalResult same = tone_map_local(s, o);
  for (std::size_t i = 0; i < s.beauty.size(); ++i) ASSERT_NEAR(same.rgb[i], s.beauty[i], 1e-5f * s.beauty[i]);
}

// detail=illumination: with the illumination flat, a checkerboard albedo comes back at its full
// contrast (4:1), whatever the curve does to the illumination.
TEST(LocalDrago, IlluminationDetailKeepsTheTextureContrast) {
  scene::Frame s = plane_scene(48, 48, [](int, int) { return 0.f; });
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      const std::size_t i = std::size_t(y) * 48 + x;
      const float a = ((x / 2 + y / 2) % 2) ? 0.8f : 0.2f;
      for (int c = 0; c < 3; ++c) s.albedo[3 * i + c] = a, s.beauty[3 * i + c] = 3.f * a;
    }
  LocalOptions o = with("exact", 100, 0.5);
  o.detail = LocalOptions::Detail::Illumination;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_NEAR(r.explain.albedo_mean, 0.4, 1e-4);  // log-average of 0.2 and 0.8
  EXPECT_NEAR(r.explain.albedo_valid_fraction, 1.0, 1e-9);
  const std::size_t dark = 24 * 48 + 24, bright = 24 * 48 + 26;  // (24,24): albedo 0.2; (26,24): 0.8
  EXPECT_NEAR(r.rgb[3 * bright] / r.rgb[3 * dark], 4.0, 0.04);
  // And the illumination itself (3 * 0.4) goes through the curve.
  EXPECT_NEAR(r.rgb[3 * dark], 0.5 * drago_by_hand(1.2, 100, 0.5), 1e-3);
}

// detail=illumination: multiplicative noise on the lighting of a flat surface is lighting, so it is
// compressed at the curve's slope (log-log) at the base; detail=luminance keeps it at full contrast.
TEST(LocalDrago, IlluminationDetailCompressesLightingNoiseAtTheCurvesSlope) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(0.7f, 1.3f);
  std::vector<float> field(64 * 64);
  for (float& v : field) v = 20.f * noise(rng);
  const scene::Frame s = plane_scene(64, 64, [&](int x, int y) { return field[std::size_t(y) * 64 + x]; });
  auto log_std = [&](const std::vector<float>& rgb) {  // over the centre, away from the borders
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int y = 16; y < 48; ++y)
      for (int x = 16; x < 48; ++x) {
        const double v = std::log10(double(rgb[3 * (std::size_t(y) * 64 + x)]));
        sum += v, sum2 += v * v, ++n;
      }
    return std::sqrt(sum2 / n - (sum / n) * (sum / n));
  };
  const double in = log_std(s.beauty);
  LocalOptions o = with("exact", 1000, 0.5);
  const double lum = log_std(tone_map_local(s, o).rgb);
  o.detail = LocalOptions::Detail::Illumination;
  const double ill = log_std(tone_map_local(s, o).rgb);
  // The slope of Drago's curve (written out by hand) at the mean illumination, in log-log.
  const double slope = std::log(drago_by_hand(20 * 1.05, 1000, 0.5) / drago_by_hand(20 / 1.05, 1000, 0.5)) / (2 * std::log(1.05));
  EXPECT_NEAR(lum / in, 1.0, 0.05);
  EXPECT_NEAR(ill / in, slope, 0.05);
  EXPECT_LT(slope, 0.8);
}

// output=scene-linear: a lone pixel at the input ceiling in a dark frame has a dark base, so the toe
// lifts it with its base; it stays at the ceiling the reader holds inputs to (65504, half float's
// largest value), where it would otherwise come out many times over it.
TEST(LocalDrago, SceneLinearOutputStaysUnderTheInputCeiling) {
  scene::Frame s = plane_scene(32, 32, [](int x, int y) { return x == 16 && y == 16 ? 65504.f : 1e-6f; });
  LocalOptions o = with("exact", 0, 1.0);
  o.output = LocalOptions::Output::SceneLinear;
  const LocalResult r = tone_map_local(s, o);
  float top = 0;
  for (float v : r.rgb) top = std::max(top, v);
  EXPECT_LE(top, 65504.f);
  EXPECT_GT(top, 1.f);  // still the brightest thing in the frame, far above Lw_a
}

// A render with alpha is the same render: the pipeline reads its colour with stride 4, tone-maps
// exactly what the RGB frame gives, and exposure scales the colour, never the coverage.
TEST(LocalDrago, AlphaIsCoverageNotColour) {
  const scene::Frame rgb = plane_scene(24, 16, [](int x, int y) { return 0.02f + 0.3f * float((x * 7 + y * 3) % 11); });
  scene::Frame rgba = rgb;
  rgba.channels = 4;
  rgba.beauty.assign(rgb.pixel_count() * 4, 0.f);
  for (std::size_t i = 0; i < rgb.pixel_count(); ++i) {
    for (int c = 0; c < 3; ++c) rgba.beauty[4 * i + c] = rgb.beauty[3 * i + c];
    rgba.beauty[4 * i + 3] = float(i % 5) / 4.f;
  }
  for (const auto& f : cgtmo::local::test::operator_filters()) {
    LocalOptions o;
    o.filter = f;
    const LocalResult a = tone_map_local(rgb, o), b = tone_map_local(rgba, o);
    ASSERT_EQ(a.rgb.size(), b.rgb.size()) << f;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) ASSERT_EQ(a.rgb[i], b.rgb[i]) << f << " value " << i;
  }
  expose_scene(rgba, 4.0);
  for (std::size_t i = 0; i < rgb.pixel_count(); ++i) {
    for (int c = 0; c < 3; ++c) ASSERT_EQ(rgba.beauty[4 * i + c], 4.f * rgb.beauty[3 * i + c]) << "pixel " << i;
    ASSERT_EQ(rgba.beauty[4 * i + 3], float(i % 5) / 4.f) << "pixel " << i;
  }
  scene::Frame bad = rgba;
  bad.beauty.pop_back();  // not width*height*channels
  EXPECT_THROW(tone_map_local(bad, LocalOptions{}), cgtmo::DataError);
}
