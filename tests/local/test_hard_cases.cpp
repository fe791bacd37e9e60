// Section 7's hard cases: finite output in [0, 1], no crash, the documented behaviour
// (docs/cgtmo.md, "Hard cases"), for every filter; and where the output is known, compared with
// it (the final clamp keeps even an all-black image in [0, 1], so the range alone proves little).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cgtmo/local/local_drago.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/operators/drago_curve.h"
#include "cgtmo/scene/sanitize.h"
#include "scene_builder.h"

using namespace cgtmo::local;
namespace scene = cgtmo::scene;
using cgtmo::local::test::drago_by_hand;
using cgtmo::local::test::plane_scene;

namespace {

const std::vector<std::string> kFilters = cgtmo::local::test::operator_filters();

void expect_ok(const scene::Frame& s, const LocalOptions& o, const std::string& what) {
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
void for_each_filter(const scene::Frame& s, F&& tweak, const std::string& what) {
  for (const auto& f : kFilters) {
    LocalOptions o;
    o.filter = f;
    tweak(o);
    expect_ok(s, o, what + " / " + f);
  }
}

auto no_tweak = [](LocalOptions&) {};

// How far `fast` and `poisson` may be from `exact` on the textured frames below: the base in log10
// units, the output in display values; `fast` by its largest difference, `poisson` (a sampled
// estimate) by the root-mean-square one. Measured on 2026-12-03 (Release, x86-64) in brackets.
struct Tolerance {
  double base, output;
};
constexpr Tolerance kFastNoGuide{2e-3, 2e-3};      // max (5.7e-4, 4.5e-4)
constexpr Tolerance kPoissonNoGuide{0.1, 0.05};    // rms (0.064, 0.035)
constexpr Tolerance kFastNarrow{5e-3, 3e-3};       // max (2.6e-3, 1.6e-3 on 60x3)
// Poisson's 2D pattern leaves few of its 32 samples inside a frame narrower than the window: rms
// 0.16 (5x60) to 0.36 (1x17) log10, and on the 1 px wide frame as far from `exact` as the
// unfiltered luminance is (0.356). This bound states that limitation, it does not excuse more.
constexpr Tolerance kPoissonNarrow{0.4, 0.2};      // rms (0.356, 0.154 on 1x17)

scene::Frame textured(int w, int h) {
  return plane_scene(w, h, [](int x, int y) { return 0.02f + 0.3f * float((x * 13 + y * 7) % 11) / 11.f; });
}

// One filter with Lw_max and Lw_a given (the scene statistics are not under test here).
LocalResult run(const scene::Frame& s, const std::string& filter, double lw_max, double lw_a) {
  LocalOptions o;
  o.filter = filter;
  o.lw_max = lw_max, o.lw_a = lw_a;
  return tone_map_local(s, o);
}

// The local formula on the result's own base layer, for grey scenes (luminance = any channel):
// Ld = TC(base) * L / base, clamped, with TC Drago's curve as the paper writes it.
void expect_local_formula(const scene::Frame& s, const LocalResult& r, double lw_max, double lw_a, const std::string& what) {
  ASSERT_EQ(r.base_log.size(), s.pixel_count()) << what;
  for (std::size_t i = 0; i < s.pixel_count(); ++i) {
    const double l = s.beauty[3 * i], base = std::pow(10.0, double(r.base_log[i]));
    const double want = std::clamp(drago_by_hand(base, lw_max, lw_a) * l / base, 0.0, 1.0);
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(r.rgb[3 * i + k], want, 1e-5) << what << " pixel " << i << " channel " << k;
  }
}

// Largest difference between two base layers (log10 units) and between two outputs.
double max_abs_diff(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, double(std::abs(a[i] - b[i])));
  return d;
}

// The cross-bilateral definition with no guide group: a spatial Gaussian (sigma_g, window
// ceil(window_sigmas sigma_g)) of the floored log10 luminance, normalised over the pixels inside
// the frame.
std::vector<float> gaussian_of_log_luminance(const scene::Frame& s, double lw_a, const cgtmo::filters::FilterParams& p = {}) {
  const int w = s.width, h = s.height;
  const int radius = int(std::ceil(double(p.window_sigmas) * p.sigma_spatial_px));
  const double floor = std::max(1e-4 * lw_a, 1e-12);
  std::vector<double> lg(s.pixel_count());
  for (std::size_t i = 0; i < lg.size(); ++i) lg[i] = std::log10(std::max(double(s.beauty[3 * i]), floor));
  std::vector<float> out(s.pixel_count());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double num = 0, den = 0;
      for (int yy = std::max(0, y - radius); yy <= std::min(h - 1, y + radius); ++yy)
        for (int xx = std::max(0, x - radius); xx <= std::min(w - 1, x + radius); ++xx) {
          const double d2 = double(xx - x) * (xx - x) + double(yy - y) * (yy - y);
          const double g = std::exp(-d2 / (2.0 * p.sigma_spatial_px * p.sigma_spatial_px));
          num += g * lg[std::size_t(yy) * w + xx];
          den += g;
        }
      out[std::size_t(y) * w + x] = float(num / den);
    }
  return out;
}

// Root-mean-square difference.
double rms_diff(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) sum += double(a[i] - b[i]) * double(a[i] - b[i]);
  return a.empty() ? 0.0 : std::sqrt(sum / double(a.size()));
}

// Mean of every output value.
double mean_output(const LocalResult& r) {
  double sum = 0;
  for (float v : r.rgb) sum += v;
  return sum / double(r.rgb.size());
}

}  // namespace

TEST(HardCases, ZeroNanInfLuminanceAfterTheSanitisePolicy) {
  scene::Frame s = textured(30, 20);
  const float inf = std::numeric_limits<float>::infinity();
  s.beauty[0] = std::nanf("");
  s.beauty[3 * 5 + 1] = inf;
  s.beauty[3 * 6 + 2] = -inf;
  for (int c = 0; c < 3; ++c) s.beauty[3 * 40 + c] = 0.f;
  const auto rep = cgtmo::scene::sanitize(s.beauty.data(), s.pixel_count(), 3);
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
  scene::Frame s = textured(30, 20);
  s.beauty[3 * 7] = std::nanf("");
  s.beauty[3 * 8 + 1] = std::numeric_limits<float>::infinity();
  for_each_filter(s, no_tweak, "raw non-finite");
  LocalOptions o;
  o.filter = "fast";
  const LocalResult r = tone_map_local(s, o);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(r.rgb[3 * 8 + c], 0.f);
}

TEST(HardCases, BackgroundOnly) {
  scene::Frame s = textured(20, 10);
  std::fill(s.depth.begin(), s.depth.end(), 1e10f);
  std::fill(s.position.begin(), s.position.end(), 0.f);
  for_each_filter(s, no_tweak, "all background");
  LocalOptions o;
  o.filter = "fast";
  o.lw_max = 5, o.lw_a = 0.2;
  const LocalResult r = tone_map_local(s, o);
  for (std::size_t i = 0; i < s.pixel_count(); ++i)
    ASSERT_NEAR(r.rgb[3 * i], drago_by_hand(s.beauty[3 * i], 5, 0.2), 2e-5);  // global everywhere
}

TEST(HardCases, ZeroLengthAndUnnormalisedNormals) {
  scene::Frame s = textured(24, 16);
  scene::Frame scaled = s;
  for (std::size_t i = 0; i < s.pixel_count(); ++i)
    for (int k = 0; k < 3; ++k) scaled.normal[3 * i + k] *= 0.2f;  // Blender's silhouette lengths
  for (const auto& f : {"exact", "fast"}) {
    LocalOptions o;
    o.filter = f;
    o.model_guide = false;
    const LocalResult a = tone_map_local(s, o), b = tone_map_local(scaled, o);
    for (std::size_t i = 0; i < a.rgb.size(); ++i) ASSERT_NEAR(a.rgb[i], b.rgb[i], 1e-6) << f;  // renormalised
  }
  scene::Frame zero = s;
  for (int k = 0; k < 3; ++k) zero.normal[3 * 50 + k] = 0.f;
  for (int k = 0; k < 3; ++k) zero.normal[3 * 51 + k] = std::nanf("");
  for_each_filter(zero, [](LocalOptions& o) { o.model_guide = false; }, "zero normal");
  LocalOptions o;
  o.filter = "exact";
  o.model_guide = false;
  o.lw_max = 10, o.lw_a = 0.1;
  const LocalResult r = tone_map_local(zero, o);
  EXPECT_EQ(r.explain.invalid_normals, 2u);
  EXPECT_NEAR(r.rgb[3 * 50], std::min(1.0, drago_by_hand(zero.beauty[3 * 50], 10, 0.1)), 2e-5);  // global there
}

TEST(HardCases, ZeroAlbedo) {
  // Half the frame without albedo (DiffCol is 0 on emitters and metals): finite, in range, and the
  // local formula on whatever base the filter made.
  scene::Frame s = textured(24, 16);
  for (std::size_t i = 0; i < s.pixel_count() / 2; ++i)
    for (int k = 0; k < 3; ++k) s.albedo[3 * i + k] = 0.f;
  for_each_filter(s, no_tweak, "zero albedo");
  for (const auto& f : kFilters) expect_local_formula(s, run(s, f, 1, 0.1), 1, 0.1, "half zero albedo / " + f);
  // No albedo anywhere carries no information: the same result as a render without the pass.
  std::fill(s.albedo.begin(), s.albedo.end(), 0.f);
  for_each_filter(s, no_tweak, "all albedo zero");
  scene::Frame without = s;
  without.albedo.clear();
  for (const auto& f : kFilters) {
    const LocalResult zero = run(s, f, 1, 0.1), none = run(without, f, 1, 0.1);
    EXPECT_LE(max_abs_diff(zero.rgb, none.rgb), 1e-6) << f;
    EXPECT_LE(max_abs_diff(zero.base_log, none.base_log), 1e-6) << f;
    expect_local_formula(s, zero, 1, 0.1, "all albedo zero / " + f);
  }
}

TEST(HardCases, LwMaxBelowLwA) {
  // Lw_max = 0.01 below Lw_a = 5: the curve still rises (its scale 1 / log10(1 + Lw_max / Lw_a)
  // is large). Luminances of 1e-3 to 4e-3 keep its output below 1, so nothing hides in the clamp.
  const double lw_max = 0.01, lw_a = 5.0;
  const auto tc = cgtmo::operators::make_drago(0.85, 100, lw_max, lw_a);
  auto below = [&](LocalOptions& o) { o.lw_max = lw_max, o.lw_a = lw_a; };
  // A flat frame: the base is the frame itself, so every filter gives the global curve's output.
  const scene::Frame flat = plane_scene(24, 16, [](int, int) { return 0.002f; });
  const double global = tc(0.002);
  ASSERT_GT(global, 0.05);
  ASSERT_LT(global, 1.0);
  for (const auto& f : kFilters) {
    const LocalResult r = run(flat, f, lw_max, lw_a);
    for (float v : r.rgb) ASSERT_NEAR(v, global, 1e-5) << f;
  }
  // A textured frame: the local formula on each filter's base, and an output no darker than the
  // curve allows: the base is a weighted mean of luminances in [lo, hi], so each pixel gets at
  // least min TC over [lo, hi] times lo / hi.
  const float lo = 0.001f, hi = 0.004f;
  const scene::Frame s = plane_scene(24, 16, [&](int x, int y) { return lo + (hi - lo) * float((x * 13 + y * 7) % 11) / 10.f; });
  for_each_filter(s, below, "lw_max < lw_a");
  double floor_out = 1.0;
  for (int i = 0; i <= 100; ++i) floor_out = std::min(floor_out, tc(lo + (hi - lo) * i / 100.0) * lo / hi);
  for (const auto& f : kFilters) {
    const LocalResult r = run(s, f, lw_max, lw_a);
    expect_local_formula(s, r, lw_max, lw_a, "lw_max < lw_a / " + f);
    EXPECT_GT(mean_output(r), floor_out) << f;
  }
}

TEST(HardCases, AllBlackProbe) {
  scene::Frame s = textured(24, 16);
  s.probe = test::probe(64, 32, [](int) { return 0.f; });
  for_each_filter(s, no_tweak, "black probe");
  LocalOptions o;
  const LocalResult r = tone_map_local(s, o);
  EXPECT_NE(r.explain.stats.lw_a_source.find("image"), std::string::npos);
}

TEST(HardCases, OneLightAndNoLights) {
  scene::Frame s = textured(24, 16);
  s.has_sidecar = true;
  s.lights = {{"key", "AREA", "key", 25.0}};
  s.light_groups = {test::light_group("key", std::vector<float>(s.pixel_count(), 0.1f))};
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
  const scene::Frame s = plane_scene(1, 1, [](int, int) { return 0.5f; });
  for_each_filter(s, no_tweak, "1x1");
  LocalOptions o;
  o.lw_max = 4, o.lw_a = 0.25;
  EXPECT_NEAR(tone_map_local(s, o).rgb[0], drago_by_hand(0.5, 4, 0.25), 2e-5);
  scene::Frame black = plane_scene(1, 1, [](int, int) { return 0.f; });
  for_each_filter(black, no_tweak, "1x1 black");
}

TEST(HardCases, NarrowerThanTheFilterWindow) {
  // sigma_s 8 px: the window is 49 px wide; these frames are 1-5 px across. The approximations
  // must still agree with the definition (exact), and every output follow the local formula.
  for (const auto& [w, h] : {std::pair{5, 60}, std::pair{60, 3}, std::pair{1, 17}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    const scene::Frame s = textured(w, h);
    for_each_filter(s, no_tweak, size);
    const LocalResult exact = run(s, "exact", 1, 0.1);
    expect_local_formula(s, exact, 1, 0.1, size + " / exact");
    for (const auto& f : kFilters) {
      const LocalResult r = run(s, f, 1, 0.1);
      expect_local_formula(s, r, 1, 0.1, size + " / " + f);
      if (f == "fast") {
        EXPECT_LE(max_abs_diff(r.base_log, exact.base_log), kFastNarrow.base) << size;
        EXPECT_LE(max_abs_diff(r.rgb, exact.rgb), kFastNarrow.output) << size;
      } else if (f == "poisson") {
        EXPECT_LE(rms_diff(r.base_log, exact.base_log), kPoissonNarrow.base) << size;
        EXPECT_LE(rms_diff(r.rgb, exact.rgb), kPoissonNarrow.output) << size;
      }
    }
  }
}

TEST(HardCases, NoGBufferAtAll) {
  scene::Frame s = textured(40, 30);
  s.position.clear();
  s.normal.clear();
  s.albedo.clear();
  s.depth.clear();
  for_each_filter(s, no_tweak, "beauty only");
  // Without any guide the cross-bilateral base is a plain spatial Gaussian of log luminance.
  const LocalResult exact = run(s, "exact", 1, 0.1);
  EXPECT_LE(max_abs_diff(exact.base_log, gaussian_of_log_luminance(s, 0.1)), 1e-5);
  for (const auto& f : kFilters) {
    const LocalResult r = run(s, f, 1, 0.1);
    expect_local_formula(s, r, 1, 0.1, "beauty only / " + f);
    if (f == "fast") {
      EXPECT_LE(max_abs_diff(r.base_log, exact.base_log), kFastNoGuide.base);
      EXPECT_LE(max_abs_diff(r.rgb, exact.rgb), kFastNoGuide.output);
    } else if (f == "poisson") {
      EXPECT_LE(rms_diff(r.base_log, exact.base_log), kPoissonNoGuide.base);
      EXPECT_LE(rms_diff(r.rgb, exact.rgb), kPoissonNoGuide.output);
    }
  }
  // A uniform frame: the base is the frame, and the output is the global curve exactly.
  scene::Frame flat = plane_scene(20, 12, [](int, int) { return 0.3f; });
  flat.position.clear();
  flat.normal.clear();
  flat.albedo.clear();
  flat.depth.clear();
  const double global = cgtmo::operators::make_drago(0.85, 100, 1, 0.1)(0.3);
  ASSERT_GT(global, 0.1);
  ASSERT_LT(global, 1.0);
  for (const auto& f : kFilters) {
    const LocalResult r = run(flat, f, 1, 0.1);
    for (float b : r.base_log) ASSERT_NEAR(b, std::log10(0.3), 1e-5) << f;
    for (float v : r.rgb) ASSERT_NEAR(v, global, 1e-5) << f;
  }
}
