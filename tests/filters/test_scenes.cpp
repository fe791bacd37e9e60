// The approximations against the exact filter on whole scenes: the synthetic room of
// filters/synthetic.h here; the committed Blender renders in test_committed_scenes.cpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "cgtmo/filters/guide.h"
#include "cgtmo/filters/synthetic.h"

using namespace cgtmo::filters;

namespace {

struct Errors {
  double fast, separable, poisson32;
};

Errors measure(int w, int h, float noise) {
  const SyntheticScene s = make_synthetic_scene(w, h, noise);
  const GuidedInput in = s.view();
  FilterParams p;
  std::vector<float> ex(in.pixel_count()), out(in.pixel_count());
  cross_bilateral_exact(in, p, ex.data());
  Errors e{};
  cross_bilateral_fast(in, p, out.data());
  e.fast = rmse_valid(out.data(), ex.data(), in);
  cross_bilateral_separable(in, p, out.data());
  e.separable = rmse_valid(out.data(), ex.data(), in);
  p.poisson_samples = 32;
  cross_bilateral_poisson(in, p, out.data());
  e.poisson32 = rmse_valid(out.data(), ex.data(), in);
  return e;
}

}  // namespace

// Bounds: the errors measured when the methods were designed (docs/speed-vs-error.md), with a
// margin of about 20% (fast: the 0.003 target), so a regression in any evaluation fails here.
TEST(ScenesSynthetic, ApproximationsStayNearExact) {
  const Errors e = measure(480, 270, 0.02f);
  printf("fast %.5f separable %.5f poisson32 %.5f\n", e.fast, e.separable, e.poisson32);
  EXPECT_LT(e.fast, 0.0030) << "fast";  // the target itself (measured 0.00068; 0.0025 before the direct evaluation)
  EXPECT_LT(e.separable, 0.0072) << "separable";  // measured 0.0060
  EXPECT_LT(e.poisson32, 0.0135) << "poisson 32";  // measured 0.0112
  // Poisson's error is mostly the noise its few samples let through: fewer than fast's.
  EXPECT_GT(e.poisson32, e.fast);
}

// Monte Carlo noise (0.3 log10 per pixel, multiplicative): the coarse level's kernel must be close
// to the definition's everywhere, or the noise shows through its differences. With a box gather
// (each pixel to its own cell's node) the stages' kernel was a staircase across cell borders:
// 0.0035 here; with the B-spline gather 0.0015-0.0017.
TEST(ScenesSynthetic, MonteCarloNoise) {
  const Errors e = measure(480, 270, 0.3f);
  printf("noise 0.3: fast %.5f separable %.5f poisson32 %.5f\n", e.fast, e.separable, e.poisson32);
  EXPECT_LT(e.fast, 0.0025) << "fast";
}
