// The approximations against the exact filter on every committed Blender render
// (tests/scenes/<name>/<name>.exr, as the quality report finds them), read the way the benchmark
// reads them (bench/scene_guide.h). The bounds are the errors measured when this test was written
// plus a margin (regression guards); for `fast` never above the 0.003 target, which is also the
// bound of a scene added later (docs/speed-vs-error.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cgtmo/filters/guide.h"
#include "cgtmo/local/evaluate.h"
#include "scene_guide.h"

using namespace cgtmo;

TEST(ScenesCommitted, ApproximationsAgainstExact) {
  const std::filesystem::path root = std::filesystem::path(CGTMO_SOURCE_DIR) / "tests" / "scenes";
  // fast (default settings) RMSE measured at 480x270 (cornell 0.0012, two-rooms 0.0014,
  // sun-window 0.0019, night 0.0028, relief 0.0028, colored-lights 0.0009; later dark-doorway 0.0020,
  // lit-box 0.0021), x1.3 but never above the 0.003 target; a scene not listed: the target itself.
  // With a box gather and the centre pixel as every cell's representative (the first six):
  // 0.0014, 0.0044, 0.0050, 0.0077, 0.0062, 0.0016; before the direct evaluation of the pixels the
  // nodes do not describe (s=2, two scales alone): 0.0049, 0.0089, 0.064, 0.025, 0.030, 0.0034.
  const std::map<std::string, double> fast_bound = {{"cornell", 0.0016}, {"two-rooms", 0.0018},
                                                    {"sun-window", 0.0025}, {"night", 0.0030},
                                                    {"relief", 0.0030},  {"colored-lights", 0.0012},
                                                    {"dark-doorway", 0.0026}, {"lit-box", 0.0027}};
  int scenes = 0;
  for (const std::string& path : local::find_scene_files(root.string())) {
    const std::filesystem::path exr = path;
    const std::string name = exr.stem().string();
    if (exr.parent_path().filename() == "bench") continue;  // 1920x1080: the benchmark's frame
    ++scenes;
    bench::GuideFrame f;
    bench::load_guide_frame(exr.string(), f);
    const filters::GuidedInput& in = f.input;
    filters::FilterParams p;
    p.groups = bench::available_groups(in);
    std::vector<float> ex(in.pixel_count()), out(in.pixel_count());
    filters::cross_bilateral_exact(in, p, ex.data());
    filters::cross_bilateral_fast(in, p, out.data());
    const double fast = filters::rmse_valid(out.data(), ex.data(), in);
    for (float v : out) ASSERT_FALSE(std::isnan(v)) << name;
    filters::cross_bilateral_separable(in, p, out.data());
    const double sep = filters::rmse_valid(out.data(), ex.data(), in);
    p.poisson_samples = 32;
    filters::cross_bilateral_poisson(in, p, out.data());
    const double poisson = filters::rmse_valid(out.data(), ex.data(), in);
    std::printf("%-15s fast %.5f  separable %.5f  poisson32 %.5f\n", name.c_str(), fast, sep, poisson);
    const auto it = fast_bound.find(name);
    EXPECT_LT(fast, it == fast_bound.end() ? 0.003 : it->second) << name;
    EXPECT_LT(sep, 0.03) << name;       // measured at most 0.021 (sun-window)
    EXPECT_LT(poisson, 0.25) << name;   // measured at most 0.18 (night: dark and noisy)
  }
  if (scenes == 0) GTEST_SKIP() << "no committed scenes under " << root;
}
