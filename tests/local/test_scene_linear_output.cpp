// `--op cgtmo -p output=scene-linear` on every committed scene, finished by display transforms it
// knows nothing about: Blender's Filmic view and the agx view of our config. Against the same view
// on the original render: fewer white-clipped pixels (none where the original clips none); a higher
// TMQI wherever the pre-compression changed more than 0.1% of the 8-bit picture (the same within
// 1e-5 where it changed less); a value at Lw_a (mid grey), and every one between the toe's knee and
// Lw_a, keeps its level within 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cgtmo/local/evaluate.h"
#include "cgtmo/local/local_drago.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/color/luminance.h"
#include "cgtmo/display/display.h"
#include "cgtmo/metrics/tmqi.h"

namespace fs = std::filesystem;
using namespace cgtmo;
using namespace cgtmo::local;

namespace {

const fs::path kScenes = fs::path(CGTMO_SOURCE_DIR) / "tests" / "scenes";
const fs::path kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";
const fs::path kOurConfig = fs::path(CGTMO_SOURCE_DIR) / "ocio_config" / "config.ocio";

struct Finished {
  std::size_t clipped = 0;  // pixels burnt to white: every channel at the 8-bit maximum
  double q = 0, S = 0, N = 0;  // TMQI against the original render
  std::vector<float> codes;    // the 8-bit picture
};

// `scene_linear` has 3 floats per pixel.
Finished finish(const std::vector<float>& scene_linear, const scene::Frame& s, const display::DisplayEncoder& view) {
  std::vector<float> px = scene_linear;
  view.apply(px.data(), s.width, s.height, 3);
  Finished f;
  for (std::size_t i = 0; i < s.pixel_count(); ++i) {
    bool clip = true;
    for (int c = 0; c < 3; ++c) {
      float& v = px[3 * i + c];
      v = std::round(std::min(std::max(v, 0.f), 1.f) * 255.f);  // as an 8-bit PNG holds it
      clip &= v >= 255.f;
    }
    f.clipped += clip;
  }
  const auto t = metrics::tmqi_rgb(s.beauty.data(), s.channels, px.data(), 3, s.width, s.height);
  f.q = t.q, f.S = t.s, f.N = t.n;
  f.codes = std::move(px);
  return f;
}

}  // namespace

TEST(SceneLinearOutput, ViewsClipFewerHighlightsAndMidGreyStays) {
  if (!fs::exists(kBlenderConfig)) GTEST_SKIP() << "Blender's OCIO config is not installed (scripts/install-deps.sh installs it)";
  const auto blender = display::load_config(kBlenderConfig.string());
  const auto ours = display::load_config(kOurConfig.string());
  const display::DisplayEncoder filmic(blender, "sRGB", "Filmic");
  const display::DisplayEncoder agx(ours, "sRGB", "agx");
  const operators::OperatorDef* op = &find_scene_operator("cgtmo");
  const LocalOptions lo = options_from(*op, operators::resolve_params(*op, {{"output", "scene-linear"}}, nullptr));
  const auto files = find_scene_files(kScenes.string());
  ASSERT_GE(files.size(), 7u);
  for (const auto& path : files) {
    SCOPED_TRACE(path);
    LoadRequest req;
    req.path = path;
    const scene::Frame s = load_scene(req).scene;
    const LocalResult r = tone_map_local(s, lo);
    const std::vector<float> rgb = scene::rgb_of(s);  // the render without its alpha
    for (const auto* view : {&filmic, &agx}) {
      SCOPED_TRACE(view->view());
      const Finished before = finish(rgb, s, *view), after = finish(r.rgb, s, *view);
      std::size_t changed = 0;  // pixels whose 8-bit picture the pre-compression changed
      for (std::size_t i = 0; i < s.pixel_count(); ++i)
        changed += before.codes[3 * i] != after.codes[3 * i] || before.codes[3 * i + 1] != after.codes[3 * i + 1] ||
                   before.codes[3 * i + 2] != after.codes[3 * i + 2];
      std::printf("%s %s: %zu px changed, clipped %zu -> %zu, TMQI %.7f -> %.7f (S %.4f -> %.4f, N %.4f -> %.4f; Lw_a %.4g, base up to %.2f "
                  "stops above it, k %.3f)\n",
                  fs::path(path).stem().c_str(), view->view().c_str(), changed, before.clipped, after.clipped, before.q, after.q,
                  before.S, after.S, before.N, after.N, r.explain.stats.lw_a, r.explain.base_headroom_stops, r.explain.pre.k_high);
      if (before.clipped > 0)
        EXPECT_LT(after.clipped, before.clipped);
      else
        EXPECT_EQ(after.clipped, 0u);
      // Higher wherever the pre-compression changed more than 0.1% of the picture; where it changed
      // less (a few pixels of a render that fits the view), the same within 1e-5.
      if (changed * 1000 > s.pixel_count())
        EXPECT_GT(after.q, before.q);
      else
        EXPECT_NEAR(after.q, before.q, 1e-5);
    }
    // Mid grey: pixels whose base layer lies between the toe's knee and Lw_a (+0.5%) keep their
    // luminance within 1%.
    const double lw_a = r.explain.stats.lw_a;
    ASSERT_GT(r.explain.pre.knee_low, 0.0);
    const double lowest = lw_a * std::exp2(-r.explain.pre.knee_low);
    std::size_t at_or_below_grey = 0, moved = 0;
    for (std::size_t i = 0; i < s.pixel_count(); ++i) {
      const double base = std::pow(10.0, r.base_log[i]);
      if (base > lw_a * 1.005 || base < lowest) continue;
      const float* c = s.rgb_at(i);
      const double in = color::luminance(c[0], c[1], c[2]);
      const double out = color::luminance(r.rgb[3 * i], r.rgb[3 * i + 1], r.rgb[3 * i + 2]);
      if (!(in > 0)) continue;
      ++at_or_below_grey;
      moved += std::abs(out / in - 1.0) > 0.01;
    }
    EXPECT_GT(at_or_below_grey, 0u);
    EXPECT_EQ(moved, 0u);
  }
}
