// The reference evaluation of guide.h's definition: every pixel of the (2R+1)^2 window, weights
// and sums in double. Slow by design (about 2400 taps per pixel at sigma_g = 8).
#include <algorithm>
#include <cmath>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

void cross_bilateral_exact(const GuidedInput& in, const FilterParams& p, float* out) {
  check_input(in, p);
  const detail::PlanarFrame f = detail::make_planar(in, p, true);
  const int w = in.width, h = in.height;
  const int radius = int(std::ceil(double(p.window_sigmas) * p.sigma_spatial_px));
  const double ks = 1.0 / (2.0 * double(p.sigma_spatial_px) * p.sigma_spatial_px);
  const double kg[3] = {0.0, 1.0 / (2.0 * double(p.sigma_normal) * p.sigma_normal),
                        1.0 / (2.0 * double(p.sigma_albedo) * p.sigma_albedo)};
  const bool active[3] = {(p.groups & kGuidePosition) != 0, (p.groups & kGuideNormal) != 0,
                          (p.groups & kGuideAlbedo) != 0};
  detail::for_each_row(h, [&](int y) {
    std::vector<double> e(std::size_t(2 * radius + 1));  // one row of exponents, reused (per row, not per pixel)
    for (int x = 0; x < w; ++x) {
      const std::size_t c = std::size_t(y) * w + x;
      if (f.valid[c] == 0.0f) {
        out[c] = in.log_lum[c];
        continue;
      }
      double cg[9];
      for (int g = 0; g < 3; ++g)
        if (active[g])
          for (int k = 0; k < 3; ++k) cg[3 * g + k] = f.guide[3 * g + k][c];
      const double kp = active[0] ? double(f.kpos[c]) : 0.0;
      const int x0 = std::max(0, x - radius), x1 = std::min(w - 1, x + radius);
      const int y0 = std::max(0, y - radius), y1 = std::min(h - 1, y + radius);
      double num = 0.0, den = 0.0;
      for (int yy = y0; yy <= y1; ++yy) {
        const double dy = yy - y;
        const std::size_t row = std::size_t(yy) * w;
        const int n = x1 - x0 + 1;
        for (int j = 0; j < n; ++j) {
          const double dx = x0 + j - x;
          e[j] = -ks * (dx * dx + dy * dy);
        }
        for (int g = 0; g < 3; ++g) {
          if (!active[g]) continue;
          const double k = g == 0 ? kp : kg[g];
          const float* a = f.guide[3 * g].data() + row + x0;
          const float* b = f.guide[3 * g + 1].data() + row + x0;
          const float* cc = f.guide[3 * g + 2].data() + row + x0;
          for (int j = 0; j < n; ++j) {
            const double d0 = a[j] - cg[3 * g], d1 = b[j] - cg[3 * g + 1], d2 = cc[j] - cg[3 * g + 2];
            e[j] -= k * (d0 * d0 + d1 * d1 + d2 * d2);
          }
        }
        const float* lum = f.lum.data() + row + x0;
        const float* valid = f.valid.data() + row + x0;
        for (int j = 0; j < n; ++j) e[j] = detail::exp_neg(e[j]) * valid[j];
        for (int j = 0; j < n; ++j) {
          num += e[j] * lum[j];
          den += e[j];
        }
      }
      out[c] = float(num / den);  // den >= 1: the centre is valid and weighs exp(0)
    }
  });
}

}  // namespace cgtmo::filters
