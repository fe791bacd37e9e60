// The classic bilateral filter of log luminance (Tomasi and Manduchi; Durand and Dorsey's base layer):
// the paper's Figure 3(a), which bleeds across objects of similar luminance because it sees no
// G-buffer. Same window, mask and background rule as the exact cross-bilateral (guide.h).
#include <algorithm>
#include <cmath>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

void cross_bilateral_bilateral(const GuidedInput& in, const FilterParams& p_in, float* out) {
  FilterParams p = p_in;
  p.groups = 0;  // luminance alone
  check_input(in, p);
  const detail::PlanarFrame f = detail::make_planar(in, p, false);
  const int w = in.width, h = in.height;
  const int radius = int(std::ceil(double(p.window_sigmas) * p.sigma_spatial_px));
  const double ks = 1.0 / (2.0 * double(p.sigma_spatial_px) * p.sigma_spatial_px);
  const double kr = 1.0 / (2.0 * double(p.sigma_range_log10) * p.sigma_range_log10);
  detail::for_each_row(h, [&](int y) {
    std::vector<double> e(std::size_t(2 * radius + 1));
    for (int x = 0; x < w; ++x) {
      const std::size_t c = std::size_t(y) * w + x;
      if (f.valid[c] == 0.0f) {
        out[c] = in.log_lum[c];
        continue;
      }
      const double lc = f.lum[c];
      const int x0 = std::max(0, x - radius), x1 = std::min(w - 1, x + radius);
      const int y0 = std::max(0, y - radius), y1 = std::min(h - 1, y + radius);
      double num = 0.0, den = 0.0;
      for (int yy = y0; yy <= y1; ++yy) {
        const double dy = yy - y;
        const float* lum = f.lum.data() + std::size_t(yy) * w + x0;
        const float* valid = f.valid.data() + std::size_t(yy) * w + x0;
        const int n = x1 - x0 + 1;
        for (int j = 0; j < n; ++j) {
          const double dx = x0 + j - x, dl = lum[j] - lc;
          e[j] = detail::exp_neg(-ks * (dx * dx + dy * dy) - kr * dl * dl) * valid[j];
        }
        for (int j = 0; j < n; ++j) {
          num += e[j] * lum[j];
          den += e[j];
        }
      }
      out[c] = float(num / den);
    }
  });
}

}  // namespace cgtmo::filters
