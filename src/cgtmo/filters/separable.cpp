// The separable evaluation: the 2-D window of guide.h factored into a horizontal then a vertical 1-D
// pass that carry numerator and denominator separately (homogeneous coordinates):
//   num1(z) = sum_dx g(dx) f(z, z+dx) L(z+dx),   den1(z) = sum_dx g(dx) f(z, z+dx)
//   base(x) = sum_dy g(dy) f(x, x+dy) num1(x+dy) / sum_dy g(dy) f(x, x+dy) den1(x+dy)
// so pixel y = x + (dx, dy) weighs g(dx) g(dy) f(x, z) f(z, y) with z = x + (0, dy) the corner of
// the L-shaped path. The spatial Gaussian factors exactly; the guide factor is exact wherever the
// guide is constant or varies linearly along perpendicular world directions (a surface facing the
// camera: |P(x)-P(y)|^2 = |P(x)-P(z)|^2 + |P(z)-P(y)|^2), and across an edge either leg's factor
// vanishes, so nothing leaks. Carrying den1 (instead of normalising after the first pass, as the
// separable bilateral of Pham and van Vliet does) keeps each row's share proportional to the mass
// it really has. Cost: 2 (2R+1) taps per pixel instead of (2R+1)^2, with R a few effective sigmas
// (sigma_g / sqrt 2 where the position factor acts as a second spatial Gaussian).
// Floats and a polynomial exp2 (relative error 3e-6), SIMD over x, rows over the pool.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/simd_kernels.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

namespace {

using detail::kLog2e;

int round_up(int v, int m) { return (v + m - 1) / m * m; }

}  // namespace

int fast_radius(const FilterParams& p) {
  // Where the position factor is active it narrows the kernel to sigma_g / sqrt 2 on surfaces
  // facing the camera (and more on slanted ones); elsewhere the spatial sigma alone sets it.
  const double sigma = (p.groups & kGuidePosition) ? p.sigma_spatial_px / std::sqrt(2.0) : p.sigma_spatial_px;
  return std::max(1, int(std::ceil(double(p.effective_window_sigmas) * sigma)));
}

void cross_bilateral_separable(const GuidedInput& in, const FilterParams& p, float* out) {
  check_input(in, p);
  const simd_kernels::Kernels& kernels = simd_kernels::best();
  const int lanes = kernels.width;
  const int w = in.width, h = in.height;
  const unsigned groups = p.groups;
  const int radius = fast_radius(p);
  std::vector<float> spatial(std::size_t(2 * radius + 1));
  for (int t = -radius; t <= radius; ++t)
    spatial[std::size_t(t + radius)] = float(-kLog2e * t * t / (2.0 * double(p.sigma_spatial_px) * p.sigma_spatial_px));
  const float kn = float(kLog2e / (2.0 * double(p.sigma_normal) * p.sigma_normal));
  const float ka = float(kLog2e / (2.0 * double(p.sigma_albedo) * p.sigma_albedo));
  const Channel* src[3] = {in.position, in.normal, in.albedo};

  // The guide as the vertical pass reads it: the caller's planes when they are contiguous and at
  // least one vector wide (no copy), else a padded copy.
  bool direct = w >= lanes;
  for (int g = 0; g < 3; ++g)
    if (groups & (1u << g))
      for (int k = 0; k < 3; ++k) direct = direct && src[g][k].stride == 1;
  const int pitch_g = direct ? w : round_up(w, lanes);
  std::vector<float> guide_copy;
  const float* guide_base[9] = {};
  if (direct) {
    for (int g = 0; g < 3; ++g)
      if (groups & (1u << g))
        for (int k = 0; k < 3; ++k) guide_base[3 * g + k] = src[g][k].data;
  } else {
    int active = 0;
    for (int g = 0; g < 3; ++g) active += (groups >> g) & 1u;
    guide_copy.assign(std::size_t(active) * 3 * pitch_g * h, 0.0f);
    int slot = 0;
    for (int g = 0; g < 3; ++g) {
      if (!(groups & (1u << g))) continue;
      for (int k = 0; k < 3; ++k, ++slot) {
        float* dst = guide_copy.data() + std::size_t(slot) * pitch_g * h;
        guide_base[3 * g + k] = dst;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) dst[std::size_t(y) * pitch_g + x] = src[g][k][std::size_t(y) * w + x];
      }
    }
  }

  // Pass 1, horizontal: num1/den1 for every pixel (0 at invalid ones).
  const int pitch_n = round_up(w, lanes);
  std::vector<float> num1(std::size_t(pitch_n) * h), den1(std::size_t(pitch_n) * h);
  parallel_rows(h, [&](int64_t y_begin, int64_t y_end) {
    const std::size_t padded = std::size_t(w + 2 * radius + lanes);
    std::vector<float> rows(11 * padded + std::size_t(pitch_n), 0.0f);  // lm, m, 9 guide, kpos
    float* lm = rows.data();
    float* m = lm + padded;
    simd_kernels::Guide9 g9{};
    for (int k = 0; k < 9; ++k) g9.g[k] = m + padded * std::size_t(k + 1);
    float* kpos = m + padded * 10;
    for (int64_t y = y_begin; y < y_end; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * w + x, j = std::size_t(x + radius);
        const bool valid = detail::pixel_valid(in, groups, i);
        lm[j] = valid ? in.log_lum[i] : 0.0f;
        m[j] = valid ? 1.0f : 0.0f;
        for (int g = 0; g < 3; ++g)
          if (groups & (1u << g))
            for (int k = 0; k < 3; ++k) const_cast<float*>(g9.g[3 * g + k])[j] = valid ? src[g][k][i] : 0.0f;
        kpos[x] = valid ? float(kLog2e * detail::position_coefficient(in, p, i)) : 0.0f;
      }
      kernels.pass_h(groups, w, radius, spatial.data(), lm, m, g9, kpos, kn, ka, num1.data() + std::size_t(y) * pitch_n,
                     den1.data() + std::size_t(y) * pitch_n);
    }
  });

  // Pass 2, vertical, then the background rule (invalid centres keep their input).
  parallel_rows(h, [&](int64_t y_begin, int64_t y_end) {
    const std::size_t taps = std::size_t(2 * radius + 1);
    std::vector<const float*> tables(11 * taps, nullptr);
    const float* const* g_rows[9];
    for (int k = 0; k < 9; ++k) g_rows[k] = tables.data() + k * taps;
    const float** num_rows = tables.data() + 9 * taps;
    const float** den_rows = tables.data() + 10 * taps;
    std::vector<float> row(3 * std::size_t(pitch_n));
    float* kpos = row.data();
    float* lum = kpos + pitch_n;
    float* result = lum + pitch_n;
    for (int64_t y = y_begin; y < y_end; ++y) {
      for (std::size_t t = 0; t < taps; ++t) {
        const int64_t yy = y + int64_t(t) - radius;
        const bool inside = yy >= 0 && yy < h;
        for (int k = 0; k < 9; ++k)
          const_cast<const float**>(g_rows[k])[t] =
              inside && guide_base[k] ? guide_base[k] + std::size_t(yy) * pitch_g : nullptr;
        num_rows[t] = inside ? num1.data() + std::size_t(yy) * pitch_n : nullptr;
        den_rows[t] = inside ? den1.data() + std::size_t(yy) * pitch_n : nullptr;
      }
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * w + x;
        kpos[x] = float(kLog2e * detail::position_coefficient(in, p, i));
        lum[x] = in.log_lum[i];
      }
      kernels.pass_v(groups, w, pitch_g, radius, spatial.data(), g_rows, num_rows, den_rows, kpos, kn, ka, lum, result);
      std::memcpy(out + std::size_t(y) * w, result, sizeof(float) * std::size_t(w));
    }
  });
}

}  // namespace cgtmo::filters
