// Checks src/cgtmo/filters/{guide,exact,poisson,two_scale,fast,bilateral}.cpp: the cross-bilateral
// definition against hand-computed weights, and the properties every evaluation must keep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/filters/guide.h"
#include "cgtmo/filters/poisson.h"
#include "cgtmo/filters/synthetic.h"

using namespace cgtmo::filters;

namespace {

// A frame built plane by plane; view() lends it to the filters.
struct Planes {
  int w, h;
  std::vector<float> lum, mask, fp, pos[3], nrm[3], alb[3];
  Planes(int w_, int h_) : w(w_), h(h_) {
    const std::size_t n = std::size_t(w) * h;
    lum.assign(n, 0.0f);
    mask.assign(n, 1.0f);
    fp.assign(n, 0.01f);
    for (int k = 0; k < 3; ++k) {
      pos[k].assign(n, 0.0f);
      nrm[k].assign(n, 0.0f);
      alb[k].assign(n, 0.5f);
    }
    nrm[2].assign(n, 1.0f);
    // A plane facing the camera, one footprint (0.01) per pixel.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        pos[0][std::size_t(y) * w + x] = 0.01f * x;
        pos[1][std::size_t(y) * w + x] = -0.01f * y;
      }
  }
  std::size_t at(int x, int y) const { return std::size_t(y) * w + x; }
  GuidedInput view() const {
    GuidedInput in;
    in.width = w;
    in.height = h;
    in.log_lum = Channel{lum.data(), 1};
    in.mask = Channel{mask.data(), 1};
    in.footprint = Channel{fp.data(), 1};
    for (int k = 0; k < 3; ++k) {
      in.position[k] = Channel{pos[k].data(), 1};
      in.normal[k] = Channel{nrm[k].data(), 1};
      in.albedo[k] = Channel{alb[k].data(), 1};
    }
    return in;
  }
};

std::vector<float> run(FilterFunction f, const GuidedInput& in, const FilterParams& p = {}) {
  std::vector<float> out(in.pixel_count(), -999.0f);
  f(in, p, out.data());
  return out;
}

// The cross-bilateral evaluations of the filter table (wls has its own tests: test_wls.cpp), and
// those of them that read the G-buffer.
std::vector<std::string> table_names(bool guided_only) {
  std::vector<std::string> v;
  for (const auto& f : filter_table())
    if (f.function && (f.needs_gbuffer || !guided_only)) v.emplace_back(f.name);
  return v;
}
const std::vector<std::string> kGuided = table_names(true);
const std::vector<std::string> kAll = table_names(false);

FilterFunction filter_by_name(const std::string& name) { return find_filter(name).function; }

}  // namespace

// Two pixels, every factor written out from Eq. 4 with the paper's sigmas.
TEST(CrossBilateralExact, TwoPixelsByHand) {
  Planes f(2, 1);
  f.lum = {0.0f, 1.0f};
  f.pos[2][1] = 0.05f;   // second pixel 5 cm deeper: |dP|^2 = 0.01^2 + 0.05^2
  f.nrm[0][1] = 0.6f;    // normal (0.6, 0, 0.8)
  f.nrm[2][1] = 0.8f;
  f.alb[1][1] = 0.7f;    // albedo green 0.5 -> 0.7
  FilterParams p;
  const double sp = 0.01 * 8.0;  // sigma_pos of both pixels
  const double w = std::exp(-1.0 / (2 * 64.0)) * std::exp(-(0.0001 + 0.0025) / (2 * sp * sp)) *
                   std::exp(-(0.36 + 0.04) / (2 * 0.0625)) * std::exp(-0.04 / (2 * 0.0625));
  const auto out = run(&cross_bilateral_exact, f.view(), p);
  EXPECT_NEAR(out[0], w / (1.0 + w), 1e-6);
  EXPECT_NEAR(out[1], 1.0 / (1.0 + w), 1e-6);
}

// Three pixels in a row with only the spatial factor (groups off): Gaussian weights 1, e^-1/128, e^-4/128.
TEST(CrossBilateralExact, SpatialOnlyByHand) {
  Planes f(3, 1);
  f.lum = {1.0f, 2.0f, 4.0f};
  FilterParams p;
  p.groups = 0;
  const double a = std::exp(-1.0 / 128.0), b = std::exp(-4.0 / 128.0);
  const auto out = run(&cross_bilateral_exact, f.view(), p);
  EXPECT_NEAR(out[0], (1.0 + 2.0 * a + 4.0 * b) / (1.0 + a + b), 1e-6);
  EXPECT_NEAR(out[1], (2.0 + 1.0 * a + 4.0 * a) / (1.0 + 2.0 * a), 1e-6);
}

TEST(CrossBilateral, ConstantStaysConstant) {
  Planes f(37, 29);
  for (auto& v : f.lum) v = 1.25f;
  for (std::size_t i = 0; i < f.alb[0].size(); ++i) f.alb[0][i] = float(i % 7) * 0.1f;  // a busy guide
  for (const auto& name : kAll) {
    const auto out = run(filter_by_name(name), f.view());
    for (float v : out) ASSERT_NEAR(v, 1.25f, 1e-5f) << name;
  }
}

// A step in one guide group, with a luminance step on the same line: the two sides stay apart.
TEST(CrossBilateral, GuideEdgesKeepSidesApart) {
  for (int group = 0; group < 3; ++group) {
    Planes f(40, 24);
    for (int y = 0; y < f.h; ++y)
      for (int x = 20; x < f.w; ++x) {
        const std::size_t i = f.at(x, y);
        f.lum[i] = 2.0f;
        if (group == 0) f.pos[2][i] = 1.0f;  // a depth jump of 100 footprints
        if (group == 1) {
          f.nrm[0][i] = 1.0f;  // a 90-degree crease
          f.nrm[2][i] = 0.0f;
        }
        if (group == 2)
          for (int k = 0; k < 3; ++k) f.alb[k][i] = 0.9f;  // albedo 0.1 -> 0.9
      }
    if (group == 2)
      for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < 20; ++x)
          for (int k = 0; k < 3; ++k) f.alb[k][f.at(x, y)] = 0.1f;
    FilterParams p;
    p.groups = 1u << group;
    for (const auto& name : kGuided) {
      const auto out = run(filter_by_name(name), f.view(), p);
      for (int y = 0; y < f.h; ++y) {
        // Right next to the edge, on both sides.
        EXPECT_LT(out[f.at(19, y)], 0.02f) << name << " group " << group;
        EXPECT_GT(out[f.at(20, y)], 1.98f) << name << " group " << group;
      }
    }
  }
}

// The bilateral of luminance alone bleeds where two objects have similar luminance; the guide
// does not (the paper's Figure 3).
TEST(CrossBilateral, BilateralBleedsWhereGuideDoesNot) {
  Planes f(40, 24);
  for (int y = 0; y < f.h; ++y)
    for (int x = 20; x < f.w; ++x) {
      f.lum[f.at(x, y)] = 0.3f;  // within one range sigma (0.4)
      f.nrm[0][f.at(x, y)] = 1.0f;
      f.nrm[2][f.at(x, y)] = 0.0f;
    }
  const auto bil = run(&cross_bilateral_bilateral, f.view());
  const auto ex = run(&cross_bilateral_exact, f.view());
  EXPECT_GT(bil[f.at(19, 12)], 0.05f);
  EXPECT_LT(ex[f.at(19, 12)], 1e-3f);
}

TEST(CrossBilateral, BackgroundNeverLeaks) {
  Planes f(48, 32);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const bool bg = (x > 30) || (y < 5) || ((x + y) % 11 == 0);
      if (!bg) continue;
      const std::size_t i = f.at(x, y);
      f.mask[i] = 0.0f;
      f.lum[i] = 4.0f + 0.1f * float(x % 3);  // bright, textured sky
      // Background G-buffer is zeros (Blender writes Position 0 there).
      for (int k = 0; k < 3; ++k) f.pos[k][i] = f.nrm[k][i] = f.alb[k][i] = 0.0f;
    }
  for (const auto& name : kAll) {
    const auto out = run(filter_by_name(name), f.view());
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (f.mask[i] > 0.5f)
        ASSERT_NEAR(out[i], 0.0f, 1e-6f) << name << " pixel " << i;
      else
        ASSERT_EQ(out[i], f.lum[i]) << name << " background keeps its input";
    }
  }
}

TEST(CrossBilateral, OnePixelFrame) {
  Planes f(1, 1);
  f.lum[0] = -1.5f;
  for (const auto& name : kAll) EXPECT_FLOAT_EQ(run(filter_by_name(name), f.view())[0], -1.5f) << name;
}

// Frames narrower than every window (49 for exact, 35 for fast): agree with the reference.
TEST(CrossBilateral, FramesNarrowerThanTheWindow) {
  for (auto [w, h] : {std::pair{3, 50}, std::pair{50, 3}, std::pair{2, 2}, std::pair{17, 5}}) {
    Planes f(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) f.lum[f.at(x, y)] = 0.05f * float(x) - 0.03f * float(y);
    const auto ex = run(&cross_bilateral_exact, f.view());
    for (const auto& name : {"fast", "separable"}) {
      const auto out = run(filter_by_name(name), f.view());
      for (std::size_t i = 0; i < out.size(); ++i) {
        ASSERT_TRUE(std::isfinite(out[i])) << name;
        EXPECT_NEAR(out[i], ex[i], 0.01f) << name << " " << w << "x" << h << " pixel " << i;
      }
    }
  }
}

TEST(CrossBilateral, ZeroNormalsAndZeroAlbedoStayFinite) {
  Planes f(30, 20);
  for (std::size_t i = 0; i < f.lum.size(); ++i) {
    f.lum[i] = float(i % 13) * 0.1f;
    for (int k = 0; k < 3; ++k) {
      f.nrm[k][i] = (i % 3 == 0) ? 0.0f : f.nrm[k][i];  // zero-length normals
      f.alb[k][i] = 0.0f;                              // black (or metal) albedo
    }
  }
  for (const auto& name : kAll) {
    const auto out = run(filter_by_name(name), f.view());
    for (float v : out) ASSERT_TRUE(std::isfinite(v)) << name;
  }
}

// Non-finite guide or luminance at a pixel the mask calls geometry: treated as background.
TEST(CrossBilateral, NonFiniteChannelsAreBackground) {
  Planes f(30, 20);
  f.nrm[0][f.at(10, 10)] = NAN;
  f.pos[1][f.at(11, 10)] = INFINITY;
  f.lum[f.at(12, 10)] = NAN;
  for (const auto& name : kAll) {
    const auto out = run(filter_by_name(name), f.view());
    for (std::size_t i = 0; i < out.size(); ++i)
      if (i != f.at(12, 10)) {
        ASSERT_TRUE(std::isfinite(out[i])) << name << " pixel " << i;
      }
  }
}

// With every guide group off and no background, the separable passes are the 2-D Gaussian
// exactly (it factors).
TEST(CrossBilateralSeparable, EqualsExactWithoutGuide) {
  Planes f(96, 64);
  for (std::size_t i = 0; i < f.lum.size(); ++i) f.lum[i] = float((i * 2654435761u) % 1000) * 0.002f;
  FilterParams p;
  p.groups = 0;
  p.effective_window_sigmas = 3.0f;  // the same 49-pixel window as exact's 3 sigma_g
  const auto ex = run(&cross_bilateral_exact, f.view(), p);
  const auto sep = run(&cross_bilateral_separable, f.view(), p);
  EXPECT_LT(rmse_valid(sep.data(), ex.data(), f.view()), 2e-5);
}

TEST(PoissonDisk, PatternIsCentredDistinctAndSpread) {
  for (int samples : {1, 8, 16, 32, 64}) {
    const auto o = poisson_disk_offsets(samples, 8.0f, 24, 1);
    ASSERT_EQ(int(o.size()), samples);
    EXPECT_EQ(o[0].dx, 0);
    EXPECT_EQ(o[0].dy, 0);
    double second_moment = 0.0;
    for (std::size_t i = 0; i < o.size(); ++i) {
      EXPECT_LE(std::abs(o[i].dx), 24);
      EXPECT_LE(std::abs(o[i].dy), 24);
      for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(o[i].dx == o[j].dx && o[i].dy == o[j].dy);
      second_moment += o[i].dx * o[i].dx + o[i].dy * o[i].dy;
    }
    // Gaussian-distributed: E|d|^2 = 2 sigma^2 = 128 (the centre sample and the spacing move it a
    // little).
    if (samples >= 32) {
      EXPECT_NEAR(second_moment / samples, 128.0, 40.0);
    }
  }
  // Asking for the whole window returns it, nearest first.
  EXPECT_EQ(poisson_disk_offsets(9, 8.0f, 1, 1).size(), 9u);
}

// The vectorised Poisson evaluation (interior pixels in groups that share each offset, border
// pixels one by one) against the sampling definition written out here: every offset, the guide
// factors only (the spatial Gaussian is in the sampling density), background skipped.
TEST(CrossBilateralPoisson, MatchesTheSamplingDefinition) {
  Planes f(157, 61);  // not a multiple of any vector width; interior, borders and corners
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (std::size_t i = 0; i < f.lum.size(); ++i) {
    f.lum[i] = 3.0f * u(rng) - 1.0f;
    f.pos[2][i] = 0.05f * u(rng);
    for (int k = 0; k < 3; ++k) {
      f.nrm[k][i] += 0.6f * (u(rng) - 0.5f);
      f.alb[k][i] = u(rng);
    }
    f.fp[i] = 0.005f + 0.01f * u(rng);
    if (u(rng) < 0.05f) f.mask[i] = 0.0f;
  }
  const GuidedInput in = f.view();
  for (unsigned groups : {1u, 6u, 7u}) {
    FilterParams p;
    p.groups = groups;
    p.poisson_samples = 24;
    const std::vector<float> got = run(cross_bilateral_poisson, in, p);
    const int radius = int(std::ceil(p.window_sigmas * p.sigma_spatial_px));
    const auto offsets = poisson_disk_offsets(p.poisson_samples, p.sigma_spatial_px, radius, p.poisson_seed);
    double worst = 0.0;
    for (int y = 0; y < f.h; ++y)
      for (int x = 0; x < f.w; ++x) {
        const std::size_t c = f.at(x, y);
        if (f.mask[c] <= 0.5f) {
          ASSERT_EQ(got[c], f.lum[c]) << "background keeps its input";
          continue;
        }
        const double sp = f.fp[c] * p.sigma_pos_footprints;
        double num = 0.0, den = 0.0;
        for (const Offset& o : offsets) {
          const int xx = x + o.dx, yy = y + o.dy;
          if (xx < 0 || xx >= f.w || yy < 0 || yy >= f.h || f.mask[f.at(xx, yy)] <= 0.5f) continue;
          const std::size_t s = f.at(xx, yy);
          double e = 0.0;
          for (int k = 0; k < 3; ++k) {
            if (groups & kGuidePosition) e -= std::pow(f.pos[k][s] - f.pos[k][c], 2) / (2 * sp * sp);
            if (groups & kGuideNormal) e -= std::pow(f.nrm[k][s] - f.nrm[k][c], 2) / (2 * 0.25 * 0.25);
            if (groups & kGuideAlbedo) e -= std::pow(f.alb[k][s] - f.alb[k][c], 2) / (2 * 0.25 * 0.25);
          }
          num += std::exp(e) * f.lum[s];
          den += std::exp(e);
        }
        worst = std::max(worst, std::abs(got[c] - num / den));
      }
    EXPECT_LT(worst, 2e-5) << "groups " << groups;
  }
}

TEST(GuideAnalysis, DropsUniformGroups) {
  Planes f(32, 16);  // uniform albedo and normal, a plane with varying position
  const GuideAnalysis a = analyze_guide(f.view(), FilterParams{});
  EXPECT_EQ(a.informative, unsigned(kGuidePosition)) << a.explain;
  f.alb[0][5] = 0.9f;
  EXPECT_EQ(analyze_guide(f.view(), FilterParams{}).informative, unsigned(kGuidePosition | kGuideAlbedo));
}

TEST(Footprint, FromPositionsOfAPlaneFacingTheCamera) {
  Planes f(20, 10);
  GuidedInput in = f.view();
  in.footprint = Channel{};
  const auto fp = footprint_from_positions(in);
  for (float v : fp) EXPECT_NEAR(v, 0.01f, 1e-6f);
}

TEST(CrossBilateral, RejectsInconsistentInput) {
  Planes f(4, 4);
  GuidedInput in = f.view();
  std::vector<float> out(16);
  in.normal[1] = Channel{};
  EXPECT_THROW(cross_bilateral_exact(in, FilterParams{}, out.data()), cgtmo::UsageError);
  in = f.view();
  in.footprint = Channel{};
  EXPECT_THROW(cross_bilateral_fast(in, FilterParams{}, out.data()), cgtmo::UsageError);
  FilterParams p;
  p.sigma_normal = 0.0f;
  EXPECT_THROW(cross_bilateral_poisson(f.view(), p, out.data()), cgtmo::UsageError);
  EXPECT_THROW(filter_by_name("gaussian"), cgtmo::UsageError);
}

namespace {

// A textured frame with guide edges everywhere: normals and albedo change in patches, a few
// background pixels and a NaN normal; log luminance with strong noise.
Planes patchwork(int w, int h) {
  Planes f(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = f.at(x, y);
      const unsigned hsh = unsigned(i) * 2654435761u;
      f.lum[i] = -2.0f + 0.002f * float(hsh % 1000) + ((x / 7 + y / 5) % 2 ? 1.5f : 0.0f);
      const bool tilted = (x / 11 + y / 13) % 3 == 0;
      f.nrm[0][i] = tilted ? 0.6f : 0.0f;
      f.nrm[2][i] = tilted ? 0.8f : 1.0f;
      f.alb[0][i] = (x / 9) % 2 ? 0.7f : 0.2f;
      f.mask[i] = (hsh % 97 == 0) ? 0.0f : 1.0f;
    }
  f.nrm[1][f.at(w / 2, h / 2)] = NAN;
  return f;
}

}  // namespace

// The direct evaluation (the fallback of `fast` at pixels the coarse level does not describe,
// SIMD in float) is guide.h's definition: with every pixel sent to it and the reference's window,
// `fast` equals the double-precision reference to float rounding, guide groups on and off,
// borders, background and non-finite pixels included.
TEST(CrossBilateralFast, DirectEvaluationEqualsExact) {
  const Planes f = patchwork(70, 45);
  for (unsigned groups : {0u, 2u, 6u, 7u}) {
    FilterParams p;
    p.groups = groups;
    p.two_scale.min_weight = 100.0f;  // no pixel is described well enough: all direct
    p.two_scale.direct_radius = int(std::ceil(p.window_sigmas * p.sigma_spatial_px));
    p.two_scale.direct_near = 0;  // the definition over the whole window, no node stands in
    const auto ex = run(&cross_bilateral_exact, f.view(), p);
    std::size_t direct = 0;
    std::vector<float> out(ex.size());
    cross_bilateral_fast_counted(f.view(), p, out.data(), &direct);
    std::size_t valid = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      valid += f.mask[i] > 0.5f && std::isfinite(f.nrm[1][i]);
      if (!std::isfinite(ex[i])) continue;
      ASSERT_NEAR(out[i], ex[i], 2e-5f) << "groups " << groups << " pixel " << i;
    }
    EXPECT_EQ(direct, groups & kGuideNormal ? valid : valid + 1) << "groups " << groups;
  }
}

// The hard cases of the two-scale evaluation, each against the reference at the pixels concerned:
// a strip one pixel wide of another albedo (thinner than a cell), an anti-aliased albedo edge
// (one column of blended albedo between a dark, black-lit side and a bright one), and a shadow
// edge (luminance steps by 3 decades on one surface: the guide does not explain it).
// The default direct evaluation takes the cells beyond 12 px from their nodes: on the patchwork
// (edges of normal and albedo, a luminance ramp and steps) every pixel evaluated that way stays
// close to the definition.
TEST(CrossBilateralFast, DirectEvaluationWithNodesFarAway) {
  const Planes f = patchwork(70, 45);
  FilterParams p;
  p.two_scale.min_weight = 100.0f;  // all direct
  const auto ex = run(&cross_bilateral_exact, f.view(), p);
  const auto out = run(&cross_bilateral_fast, f.view(), p);
  double worst = 0.0, sq = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (std::isfinite(ex[i])) {
      const double d = std::abs(out[i] - ex[i]);
      worst = std::max(worst, d), sq += d * d, ++count;
    }
  const double rmse = std::sqrt(sq / double(count));
  std::printf("direct with far nodes: max |fast - exact| %.2e, rmse %.2e\n", worst, rmse);
  EXPECT_LT(worst, 0.01);   // measured 0.0071 (next to the luminance steps)
  EXPECT_LT(rmse, 0.0015);  // measured 0.00105
  EXPECT_GT(worst, 1e-4);  // the nodes do stand in for far pixels (with two_scale.direct_near 0: 2e-5)
}

TEST(CrossBilateralFast, ThinStripsBlendedEdgesAndShadowEdges) {
  Planes f(96, 60);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::size_t i = f.at(x, y);
      const float noise = 0.05f * float((unsigned(i) * 2654435761u) % 1000) / 1000.0f;
      float a = x < 40 ? 0.15f : 0.7f;
      if (x == 40) a = 0.45f;  // the blended column
      if (x == 70) a = 0.15f;  // the strip
      for (int k = 0; k < 3; ++k) f.alb[k][i] = a;
      f.lum[i] = (a < 0.3f ? -6.0f : -1.0f) + noise;
      if (x == 40) f.lum[i] = (y % 2 ? -6.0f : -2.5f);  // a pixel half in, half out
      if (y >= 40 && x > 44 && x < 66) f.lum[i] -= 3.0f;  // the shadow on the bright side
    }
  const auto ex = run(&cross_bilateral_exact, f.view());
  const auto fast = run(&cross_bilateral_fast, f.view());
  const FilterParams before = fast_two_scales_only();  // the previous default
  const auto old = run(&cross_bilateral_fast, f.view(), before);
  double worst = 0, worst_before = 0;
  for (int y = 0; y < f.h; ++y)
    for (int x : {39, 40, 41, 69, 70, 71, 50, 60}) {
      const std::size_t i = f.at(x, y);
      worst = std::max(worst, double(std::abs(fast[i] - ex[i])));
      worst_before = std::max(worst_before, double(std::abs(old[i] - ex[i])));
    }
  for (int x = 45; x < 66; ++x)
    for (int y : {38, 39, 40, 41}) {
      const std::size_t i = f.at(x, y);
      worst = std::max(worst, double(std::abs(fast[i] - ex[i])));
      worst_before = std::max(worst_before, double(std::abs(old[i] - ex[i])));
    }
  std::printf("largest error at the hard pixels: %.4f (previous default %.4f)\n", worst, worst_before);
  EXPECT_LT(worst, 0.02);
  EXPECT_LT(worst, worst_before);
}

// Lines one pixel wide of another normal through the centre row of every other row of cells:
// those cells' centre pixels lie on a line, in their cell's minority. With the centre as
// representative, half of the nodes describe the lines and nearly every pixel of the surface
// between them fails the tests (too little weight of its own surface around it) and is evaluated
// directly; the medoid (two_scale.majority) represents each cell by its majority surface.
TEST(CrossBilateralFast, MinorityCentresGiveWayToTheMedoid) {
  Planes f(120, 72);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::size_t i = f.at(x, y);
      const bool line = y % 6 == 1;
      f.nrm[0][i] = line ? 0.6f : 0.0f;
      f.nrm[2][i] = line ? 0.8f : 1.0f;
      const float noise = 0.3f * float((unsigned(i) * 2654435761u) % 1000) / 1000.0f;
      f.lum[i] = (line ? -0.5f : -2.0f) + noise + 0.01f * float(x);
    }
  const auto ex = run(&cross_bilateral_exact, f.view());
  auto evaluate = [&](float majority, std::size_t& direct) {
    FilterParams p;
    p.two_scale.majority = majority;
    p.two_scale.min_purity = 0.0f;  // the lines make every cell they cross textured: only the medoid here
    std::vector<float> out(ex.size());
    cross_bilateral_fast_counted(f.view(), p, out.data(), &direct);
    double sq = 0.0;
    for (std::size_t i = 0; i < ex.size(); ++i) sq += double(out[i] - ex[i]) * (out[i] - ex[i]);
    return std::sqrt(sq / double(ex.size()));
  };
  std::size_t direct_centre = 0, direct_medoid = 0;
  const double rmse_centre = evaluate(0.0f, direct_centre), rmse_medoid = evaluate(0.7f, direct_medoid);
  std::printf("lines through the cells' centres: centre pixel rmse %.5f, %zu direct; medoid rmse %.5f, %zu direct\n",
              rmse_centre, direct_centre, rmse_medoid, direct_medoid);
  EXPECT_LT(direct_medoid, direct_centre / 2);  // measured 2047 against 8640 of 8640
  EXPECT_LT(rmse_medoid, 0.003);
}

// A brick wall facing the camera: bricks 16x9 px whose albedo varies from brick to brick (weights
// 0.5-0.9 between neighbouring bricks), one-pixel mortar joints of a much lighter albedo, luminance
// following the albedo. A cell whose pixels differ in albedo stands for a mixture; with
// two_scale.min_purity such nodes do not count as describing a pixel, which is then evaluated directly.
TEST(CrossBilateralFast, TexturedCellsAreNotTrusted) {
  Planes f(120, 72);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::size_t i = f.at(x, y);
      const int row = y / 9, shifted = x + (row % 2) * 8, col = shifted / 16;
      const bool mortar = y % 9 == 0 || shifted % 16 == 0;
      const float a = mortar ? 0.75f : 0.35f + 0.05f * float((row * 7 + col * 3) % 4);
      for (int k = 0; k < 3; ++k) f.alb[k][i] = a;
      const float noise = 0.05f * float((unsigned(i) * 2654435761u) % 1000) / 1000.0f;
      f.lum[i] = std::log10(a) - 0.6f + 0.004f * float(x) + noise;
    }
  const auto ex = run(&cross_bilateral_exact, f.view());
  auto rmse = [&](const FilterParams& p) {
    const auto out = run(&cross_bilateral_fast, f.view(), p);
    double sq = 0.0;
    for (std::size_t i = 0; i < ex.size(); ++i) sq += double(out[i] - ex[i]) * (out[i] - ex[i]);
    return std::sqrt(sq / double(ex.size()));
  };
  FilterParams untested;
  untested.two_scale.min_purity = 0.0f;
  const double with_test = rmse(FilterParams{}), without = rmse(untested);
  std::printf("brick wall: rmse %.5f with the purity test, %.5f without\n", with_test, without);
  EXPECT_LT(with_test, 0.7 * without);  // measured 0.00107 against 0.00216
  EXPECT_LT(with_test, 0.0015);
}

TEST(CrossBilateralFast, RejectsBadKnobs) {
  const Planes f(8, 8);
  std::vector<float> out(64);
  const std::vector<std::function<void(FilterParams&)>> bad = {
      [](FilterParams& p) { p.two_scale.max_spread = -1.0f; },  [](FilterParams& p) { p.two_scale.ridge = NAN; },
      [](FilterParams& p) { p.two_scale.min_node_mass = 1.5f; }, [](FilterParams& p) { p.two_scale.direct_near = -1; },
      [](FilterParams& p) { p.two_scale.majority = 1.5f; },      [](FilterParams& p) { p.two_scale.share = 1.0f; },
      [](FilterParams& p) { p.two_scale.min_purity = -0.5f; }};
  for (std::size_t i = 0; i < bad.size(); ++i) {
    FilterParams p;
    bad[i](p);
    EXPECT_THROW(cross_bilateral_fast(f.view(), p, out.data()), cgtmo::UsageError) << "knob " << i;
  }
}
