// The paper's approximation: each pixel averages S neighbours instead of the (2R+1)^2 window.
// The offsets are drawn with the spatial Gaussian's density, so that factor is already in the
// sampling (importance sampling) and each sample weighs only the guide factors of guide.h.
#include "cgtmo/filters/poisson.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/simd_kernels.h"
#include "cgtmo/filters/guide.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::filters {

std::vector<Offset> poisson_disk_offsets(int samples, float sigma_px, int radius, unsigned seed) {
  const int window = (2 * radius + 1) * (2 * radius + 1);
  samples = std::max(1, std::min(samples, window));
  std::mt19937 rng(seed);
  auto uniform = [&] { return (double(rng() >> 8) + 0.5) / double(1u << 24); };  // (0, 1), portable
  // Poisson-disk with a spacing that follows the density: where the Gaussian density is rho, S
  // points are about 1 / sqrt(S rho) apart, so the minimum distance grows as exp(r^2 / 4 sigma^2)
  // away from the centre (a constant distance would push the points outwards and widen the kernel).
  const double s2 = double(sigma_px) * sigma_px;
  double c = 0.75 * std::sqrt(2.0 * M_PI * s2 / samples);
  auto spacing = [&](int dx, int dy) { return c * repro::exp(double(dx * dx + dy * dy) / (4.0 * s2)); };
  std::vector<Offset> out;
  while (true) {
    out.assign(1, Offset{0, 0});
    int failures = 0;
    while (int(out.size()) < samples && failures < 2000) {
      // Box-Muller from the engine's bits (std::normal_distribution differs between libraries).
      const double r = sigma_px * std::sqrt(-2.0 * repro::log(uniform())), a = 2.0 * M_PI * uniform();
      const int dx = int(std::lround(r * repro::cos(a))), dy = int(std::lround(r * repro::sin(a)));
      bool ok = std::abs(dx) <= radius && std::abs(dy) <= radius;
      for (const Offset& o : out) {
        if (!ok) break;
        const double ddx = o.dx - dx, ddy = o.dy - dy, d = std::min(spacing(dx, dy), spacing(o.dx, o.dy));
        ok = (ddx != 0 || ddy != 0) && ddx * ddx + ddy * ddy >= d * d;
      }
      if (ok) {
        out.push_back(Offset{dx, dy});
        failures = 0;
      } else {
        ++failures;
      }
    }
    if (int(out.size()) == samples) return out;
    c *= 0.9;  // S points do not fit at this spacing: tighten and start again
    if (c < 0.5) {
      // Degenerate request (S close to the window size): take the window's pixels nearest the centre.
      std::vector<Offset> all;
      for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) all.push_back(Offset{x, y});
      std::stable_sort(all.begin(), all.end(),
                       [](const Offset& a, const Offset& b) { return a.dx * a.dx + a.dy * a.dy < b.dx * b.dx + b.dy * b.dy; });
      all.resize(std::size_t(samples));
      return all;
    }
  }
}

void cross_bilateral_poisson(const GuidedInput& in, const FilterParams& p, float* out) {
  check_input(in, p);
  const detail::PlanarFrame f = detail::make_planar(in, p, true);
  const int w = in.width, h = in.height;
  const int radius = int(std::ceil(double(p.window_sigmas) * p.sigma_spatial_px));
  const std::vector<Offset> offsets = poisson_disk_offsets(p.poisson_samples, p.sigma_spatial_px, radius, p.poisson_seed);
  const float kg[3] = {0.0f, float(1.0 / (2.0 * double(p.sigma_normal) * p.sigma_normal)),
                       float(1.0 / (2.0 * double(p.sigma_albedo) * p.sigma_albedo))};
  const bool active[3] = {(p.groups & kGuidePosition) != 0, (p.groups & kGuideNormal) != 0,
                          (p.groups & kGuideAlbedo) != 0};
  // One pixel, scalar: the frame's borders (where a vector of pixels would read past the row).
  auto one_pixel = [&](int x, int y) {
    const std::size_t c = std::size_t(y) * w + x;
    const float kp = active[0] ? f.kpos[c] : 0.0f;
    float num = 0.0f, den = 0.0f;
    for (const Offset& o : offsets) {
      const int xx = x + o.dx, yy = y + o.dy;
      if (xx < 0 || xx >= w || yy < 0 || yy >= h) continue;
      const std::size_t s = std::size_t(yy) * w + xx;
      if (f.valid[s] == 0.0f) continue;
      float e = 0.0f;
      for (int g = 0; g < 3; ++g) {
        if (!active[g]) continue;
        float d2 = 0.0f;
        for (int k = 0; k < 3; ++k) {
          const float d = f.guide[3 * g + k][s] - f.guide[3 * g + k][c];
          d2 += d * d;
        }
        e -= (g == 0 ? kp : kg[g]) * d2;
      }
      const float wgt = repro::exp(std::max(e, -87.0f));
      num += wgt * f.lum[s];
      den += wgt;
    }
    return num / den;  // the centre offset (0, 0) makes den >= 1
  };
  // The interior in vectors of neighbouring pixels that share each offset (simd_kernels.inc).
  const simd_kernels::Kernels& kernels = simd_kernels::best();
  const int lanes = kernels.width;
  int reach = 0;
  std::vector<int> dx, dy;
  for (const Offset& o : offsets) {
    dx.push_back(o.dx);
    dy.push_back(o.dy);
    reach = std::max(reach, std::abs(o.dx));
  }
  const simd_kernels::PoissonOffsets po{dx.data(), dy.data(), int(offsets.size())};
  simd_kernels::Guide9 g9{};
  for (int k = 0; k < 9; ++k)
    if (active[k / 3]) g9.g[k] = f.guide[k].data();
  const float kn = float(detail::kLog2e * kg[1]), ka = float(detail::kLog2e * kg[2]);
  // Column strips inside each thread's rows: the window's rows of the 12 planes for a strip stay in
  // the core's cache (the frame's full width does not: 49 rows x 1920 px x 12 planes is 4.5 MB).
  const int strip = std::max(lanes, 256 / lanes * lanes);
  parallel_rows(h, [&](int64_t y_begin, int64_t y_end) {
    float block[16];
    for (int x_begin = 0; x_begin < w; x_begin += strip) {
      const int x_end = std::min(w, x_begin + strip);
      for (int y = int(y_begin); y < int(y_end); ++y) {
        float* row = out + std::size_t(y) * w;
        int x = x_begin;
        for (; x < x_end && (x < reach || x + lanes + reach > w || x + lanes > x_end); ++x) row[x] = one_pixel(x, y);
        for (; x + lanes <= x_end && x + lanes + reach <= w; x += lanes) {
          kernels.poisson_block(p.groups, x, y, w, h, po, g9, f.valid.data(), f.lum.data(), f.kpos.data(), kn, ka, block);
          std::copy(block, block + lanes, row + x);
        }
        for (; x < x_end; ++x) row[x] = one_pixel(x, y);
      }
    }
    // Background keeps its input (guide.h).
    for (std::size_t c = std::size_t(y_begin) * w, e = std::size_t(y_end) * w; c < e; ++c)
      if (f.valid[c] == 0.0f) out[c] = in.log_lum[c];
  });
}

}  // namespace cgtmo::filters
