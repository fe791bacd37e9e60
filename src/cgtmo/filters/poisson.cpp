// The paper's approximation: each pixel averages S neighbours instead of the (2R+1)^2 window.
// The offsets are drawn with the spatial Gaussian's density, so that factor is already in the
// sampling (importance sampling) and each sample weighs only the guide factors of guide.h.
#include "cgtmo/filters/poisson.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/guide.h"

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
  auto spacing = [&](int dx, int dy) { return c * std::exp(double(dx * dx + dy * dy) / (4.0 * s2)); };
  std::vector<Offset> out;
  while (true) {
    out.assign(1, Offset{0, 0});
    int failures = 0;
    while (int(out.size()) < samples && failures < 2000) {
      // Box-Muller from the engine's bits (std::normal_distribution differs between libraries).
      const double r = sigma_px * std::sqrt(-2.0 * std::log(uniform())), a = 2.0 * M_PI * uniform();
      const int dx = int(std::lround(r * std::cos(a))), dy = int(std::lround(r * std::sin(a)));
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
  detail::for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t c = std::size_t(y) * w + x;
      if (f.valid[c] == 0.0f) {
        out[c] = in.log_lum[c];
        continue;
      }
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
        const float wgt = std::exp(std::max(e, -87.0f));
        num += wgt * f.lum[s];
        den += wgt;
      }
      out[c] = num / den;  // the centre offset (0, 0) makes den >= 1
    }
  });
}

}  // namespace cgtmo::filters
