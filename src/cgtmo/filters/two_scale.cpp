// `fast`: the cross-bilateral of guide.h evaluated at two scales.
//  A. Cells of s x s pixels. Each cell's representative is a real pixel (its centre pixel when that
//     is valid), so its guide is never a blend of two surfaces. The cell's pixels are gathered onto
//     it with the guide weight f(rep, y): a pixel of another surface in the same cell weighs ~0
//     there (it is described by the cells of its own surface). The node sits at the weighted
//     centroid of the pixels it gathered.
//  B. The filter between representatives, in 2-D over a window of a few effective sigmas, with
//     num/den kept apart (homogeneous coordinates).
//  C. Each pixel x takes the num/den of the 3x3 representatives around its cell, weighted by a
//     small spatial Gaussian (sigma s/2) times f(x, rep): representatives of other surfaces drop
//     out. Where they carry almost no weight (a feature thinner than a cell), x is evaluated by the
//     definition in a small window instead.
// The blur that A and C add (box s: s^2/12, upsampling ~ (s/2)^2) is taken out of B's sigmas, so
// the three stages together have the spatial variance of the definition. Cost per pixel:
// (2r+1)^2 / s^2 taps at B plus 9 at C, against (2R+1)^2 for the definition.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/fast_isa.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

namespace {

constexpr double kLog2e = 1.4426950408889634;
int round_up(int v, int m) { return (v + m - 1) / m * m; }

// exp(-x) for the scalar parts (A and the direct pixels); float is plenty for weights.
inline float weight_of(float e) { return std::exp(std::max(e, -87.0f)); }

}  // namespace

void cross_bilateral_fast(const GuidedInput& in, const FilterParams& p, float* out) {
  check_input(in, p);
  const fast_isa::Kernels& kernels = fast_isa::best();
  const int lanes = kernels.width;
  const int w = in.width, h = in.height, s = fast_cell_size(p, in.width, in.height);
  const unsigned groups = p.groups;
  const bool pos = (groups & kGuidePosition) != 0;
  const Channel* src[3] = {in.position, in.normal, in.albedo};
  const float kn = float(1.0 / (2.0 * double(p.sigma_normal) * p.sigma_normal));
  const float ka = float(1.0 / (2.0 * double(p.sigma_albedo) * p.sigma_albedo));

  // Variances (pixels^2): the definition's effective one, and what A and C add.
  const double sg2 = double(p.sigma_spatial_px) * p.sigma_spatial_px;
  const double eff2 = pos ? sg2 / 2.0 : sg2;
  const double su = 0.5 * s, su2 = su * su;
  const double up2 = pos ? 1.0 / (1.0 / su2 + 1.0 / sg2) : su2;
  const double rho2 = std::max(0.25, (eff2 - s * s / 12.0 - up2) / eff2);  // B's sigmas shrink by sqrt(rho2)
  const int radius_nodes = std::max(1, int(std::ceil(p.fast_radius_sigmas * std::sqrt(eff2 * rho2) / s)));

  // ---- A: nodes ----
  const int nw = (w + s - 1) / s, nh = (h + s - 1) / s;
  const int pad = radius_nodes + 1;
  const int pitch = round_up(nw + 2 * pad + lanes + 1, lanes);
  const int rows = nh + 2 * pad;
  const std::size_t plane = std::size_t(pitch) * rows;
  // px, py, 9 guide, kpos, sum, mass, num, den
  std::vector<float> node_store(16 * plane, 0.0f);
  auto node_plane = [&](int k) { return node_store.data() + std::size_t(k) * plane; };
  float *npx = node_plane(0), *npy = node_plane(1), *nk = node_plane(11), *nsum = node_plane(12), *nmass = node_plane(13),
        *nnum = node_plane(14), *nden = node_plane(15);
  auto node_index = [&](int cx, int cy) { return std::size_t(cy + pad) * pitch + std::size_t(cx + pad); };
  parallel_rows(nh, [&](int64_t b, int64_t e) {
    for (int cy = int(b); cy < int(e); ++cy)
      for (int cx = 0; cx < nw; ++cx) {
        const int x0 = cx * s, y0 = cy * s, x1 = std::min(w, x0 + s), y1 = std::min(h, y0 + s);
        int rx = std::min(x0 + s / 2, x1 - 1), ry = std::min(y0 + s / 2, y1 - 1);
        if (!detail::pixel_valid(in, groups, std::size_t(ry) * w + rx)) {
          rx = -1;
          for (int yy = y0; yy < y1 && rx < 0; ++yy)
            for (int xx = x0; xx < x1; ++xx)
              if (detail::pixel_valid(in, groups, std::size_t(yy) * w + xx)) {
                rx = xx;
                ry = yy;
                break;
              }
          if (rx < 0) continue;  // no geometry in this cell: mass 0
        }
        const std::size_t r = std::size_t(ry) * w + rx, n = node_index(cx, cy);
        float rg[9] = {};
        for (int g = 0; g < 3; ++g)
          if (groups & (1u << g))
            for (int k = 0; k < 3; ++k) node_plane(2 + 3 * g + k)[n] = rg[3 * g + k] = src[g][k][r];
        const float kp = float(detail::position_coefficient(in, p, r));
        nk[n] = float(kLog2e * kp / rho2);
        double sum = 0.0, mass = 0.0, mx = 0.0, my = 0.0;
        for (int yy = y0; yy < y1; ++yy)
          for (int xx = x0; xx < x1; ++xx) {
            const std::size_t i = std::size_t(yy) * w + xx;
            if (!detail::pixel_valid(in, groups, i)) continue;
            float e = 0.0f;
            for (int g = 0; g < 3; ++g) {
              if (!(groups & (1u << g))) continue;
              float d2 = 0.0f;
              for (int k = 0; k < 3; ++k) {
                const float d = src[g][k][i] - rg[3 * g + k];
                d2 += d * d;
              }
              e -= (g == 0 ? kp : g == 1 ? kn : ka) * d2;
            }
            const float f = weight_of(e);
            sum += double(f) * in.log_lum[i];
            mass += f;
            mx += double(f) * xx;
            my += double(f) * yy;
          }
        // The node sits at the centroid of what it gathered, so no half-pixel shift creeps in.
        npx[n] = float(mx / mass);
        npy[n] = float(my / mass);
        nsum[n] = float(sum);
        nmass[n] = float(mass);
      }
  });

  // ---- B: between nodes ----
  fast_isa::NodePlanes np{};
  np.px = npx;
  np.py = npy;
  for (int k = 0; k < 9; ++k) np.g[k] = node_plane(2 + k);
  np.kpos = nk;
  np.sum = nsum;
  np.mass = nmass;
  np.pitch = pitch;
  const float spatial_b = float(-kLog2e / (2.0 * sg2 * rho2));
  const float kn2 = float(kLog2e * kn / rho2), ka2 = float(kLog2e * ka / rho2);
  parallel_rows(nh, [&](int64_t b, int64_t e) {
    std::vector<float> num(std::size_t(round_up(nw, lanes))), den(num.size());
    for (int cy = int(b); cy < int(e); ++cy) {
      const std::size_t row0 = node_index(0, cy);
      kernels.coarse_row(groups, nw, radius_nodes, spatial_b, np, int(row0), kn2, ka2, num.data(), den.data());
      std::memcpy(nnum + row0, num.data(), sizeof(float) * nw);
      std::memcpy(nden + row0, den.data(), sizeof(float) * nw);
    }
  });

  // ---- C: upsampling, and the direct evaluation where the nodes do not describe a pixel ----
  const float spatial_c = float(-kLog2e / (2.0 * su2));
  const float kn1 = float(kLog2e * kn), ka1 = float(kLog2e * ka);
  const int fine_pitch = round_up(w, lanes) + lanes;
  const int direct_radius = s + 1;
  const double ks_direct = 1.0 / (2.0 * sg2);
  parallel_rows(h, [&](int64_t b, int64_t e) {
    std::vector<float> buf(std::size_t(fine_pitch) * 14, 0.0f);
    const float* fine_g[9];
    for (int k = 0; k < 9; ++k) fine_g[k] = buf.data() + std::size_t(k) * fine_pitch;
    float* fkpos = buf.data() + std::size_t(9) * fine_pitch;
    float* flum = fkpos + fine_pitch;
    float* fvalid = flum + fine_pitch;
    float* result = fvalid + fine_pitch;
    float* need = result + fine_pitch;
    for (int y = int(b); y < int(e); ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = std::size_t(y) * w + x;
        const bool valid = detail::pixel_valid(in, groups, i);
        fvalid[x] = valid ? 1.0f : 0.0f;
        flum[x] = in.log_lum[i];
        fkpos[x] = valid ? float(kLog2e * detail::position_coefficient(in, p, i)) : 0.0f;
        for (int g = 0; g < 3; ++g)
          if (groups & (1u << g))
            for (int k = 0; k < 3; ++k) const_cast<float*>(fine_g[3 * g + k])[x] = valid ? src[g][k][i] : 0.0f;
      }
      const int cy = y / s;
      const float* node_rows[3][13];
      for (int r = 0; r < 3; ++r) {
        const std::size_t row = node_index(0, cy - 1 + r);
        node_rows[r][0] = nnum + row;
        node_rows[r][1] = nden + row;
        node_rows[r][2] = npx + row;
        node_rows[r][3] = npy + row;
        for (int k = 0; k < 9; ++k) node_rows[r][4 + k] = node_plane(2 + k) + row;
      }
      kernels.upsample_row(groups, w, s, y, spatial_c, fine_g, fkpos, flum, fvalid, node_rows, kn1, ka1,
                           p.fast_min_weight, float(p.fast_ridge * s * s), result, need);
      for (int x = 0; x < w; ++x) {
        if (need[x] == 0.0f) continue;
        // Direct evaluation of guide.h's definition in a small window.
        const std::size_t c = std::size_t(y) * w + x;
        const double kp = detail::position_coefficient(in, p, c);
        double num = 0.0, den = 0.0;
        for (int yy = std::max(0, y - direct_radius); yy <= std::min(h - 1, y + direct_radius); ++yy)
          for (int xx = std::max(0, x - direct_radius); xx <= std::min(w - 1, x + direct_radius); ++xx) {
            const std::size_t j = std::size_t(yy) * w + xx;
            if (!detail::pixel_valid(in, groups, j)) continue;
            double ex = -ks_direct * double((xx - x) * (xx - x) + (yy - y) * (yy - y));
            for (int g = 0; g < 3; ++g) {
              if (!(groups & (1u << g))) continue;
              double d2 = 0.0;
              for (int k = 0; k < 3; ++k) {
                const double d = double(src[g][k][j]) - src[g][k][c];
                d2 += d * d;
              }
              ex -= (g == 0 ? kp : g == 1 ? double(kn) : double(ka)) * d2;
            }
            const double f = detail::exp_neg(ex);
            num += f * in.log_lum[j];
            den += f;
          }
        result[x] = float(num / den);
      }
      std::memcpy(out + std::size_t(y) * w, result, sizeof(float) * std::size_t(w));
    }
  });
}

}  // namespace cgtmo::filters
