// `fast`: the cross-bilateral of guide.h evaluated at two scales.
//  A. Cells of s x s pixels. Each cell's representative is a real pixel (its centre pixel when that
//     is valid), so its guide is never a blend of two surfaces. The cell's pixels are gathered onto
//     it with the guide weight f(rep, y): a pixel of another surface in the same cell weighs ~0
//     there (it is described by the cells of its own surface). The node sits at the weighted
//     centroid of the pixels it gathered.
//  B. The filter between representatives, in 2-D over a window of a few effective sigmas, with
//     num/den kept apart (homogeneous coordinates).
//  C. Each pixel x takes the num/den of the 2x2 representatives around it, weighted by a small
//     spatial Gaussian (sigma s/2) times f(x, rep): representatives of other surfaces drop out.
//     The pixel is evaluated by the definition instead (float, SIMD along the window rows, radius
//     fast_radius: 3 effective sigmas; the cells beyond fast_direct_near pixels enter through
//     their nodes, where the weight varies little across a cell) where the nodes cannot be trusted:
//       - their total weight for x is under fast_min_weight (a feature thinner than a cell, a
//         crease line of blended normals, an anti-aliased albedo edge), counting only nodes that
//         gathered at least fast_min_node_mass of their cell (a node on a strip thinner than a
//         cell has a coarse value no better than its few pixels), or
//       - the pixel lies beyond the nodes that describe it (frame border, end of a surface), or
//       - their values spread by more than fast_max_spread (weighted standard deviation, log10):
//         they straddle a change of the signal that a plane through them would extrapolate.
//     Measured (docs/speed-vs-error.md): on the committed scenes nearly all of the two-scale
//     error sat within 3 pixels of a guide edge (normal, albedo), and on the worst (sun-window,
//     relief, night) the largest errors were anti-aliased edge pixels whose own guide is a blend
//     and thin strips narrower than a cell, where the nodes around them describe another surface.
// The blur that A and C add (box s: s^2/12, upsampling ~ (s/2)^2) is taken out of B's sigmas, so
// the three stages together have the spatial variance of the definition. Cost per pixel:
// (2r+1)^2 / s^2 taps at B plus 9 at C, against (2R+1)^2 for the definition.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/fast_isa.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

namespace {

using detail::kLog2e;
int round_up(int v, int m) { return (v + m - 1) / m * m; }

// One fine row as the kernels read it: the active guide channels, validity, log luminance and the
// position coefficient (* log2 e), contiguous, with invalid pixels' guide and coefficient zeroed.
// Plain loops over x, so that they vectorise for contiguous channels.
struct FineRow {
  float* g[9];
  float *valid, *lum, *kpos;
};

void prepare_row(const GuidedInput& in, const FilterParams& p, unsigned groups, int y, const FineRow& r) {
  const int w = in.width;
  const std::size_t row = std::size_t(y) * w;
  auto copy = [&](const Channel& c, float* dst) {
    const float* src = c.data + row * std::size_t(c.stride);
    if (c.stride == 1) {
      std::memcpy(dst, src, sizeof(float) * std::size_t(w));
    } else if (c.stride == 3) {
      for (int x = 0; x < w; ++x) dst[x] = src[3 * std::size_t(x)];
    } else {
      const std::size_t st = std::size_t(c.stride);
      for (int x = 0; x < w; ++x) dst[x] = src[std::size_t(x) * st];
    }
  };
  copy(in.log_lum, r.lum);
  if (in.mask) {
    copy(in.mask, r.valid);
    for (int x = 0; x < w; ++x) r.valid[x] = r.valid[x] > 0.5f ? 1.0f : 0.0f;
  } else {
    for (int x = 0; x < w; ++x) r.valid[x] = 1.0f;
  }
  // v - v is 0 for finite v and NaN otherwise: a finiteness test that vectorises.
  for (int x = 0; x < w; ++x) r.valid[x] = (r.lum[x] - r.lum[x] == 0.0f) ? r.valid[x] : 0.0f;
  const Channel* src[3] = {in.position, in.normal, in.albedo};
  for (int g = 0; g < 3; ++g) {
    if (!(groups & (1u << g))) continue;
    for (int k = 0; k < 3; ++k) {
      float* d = r.g[3 * g + k];
      copy(src[g][k], d);
      for (int x = 0; x < w; ++x) r.valid[x] = (d[x] - d[x] == 0.0f) ? r.valid[x] : 0.0f;
    }
  }
  for (int g = 0; g < 3; ++g) {
    if (!(groups & (1u << g))) continue;
    for (int k = 0; k < 3; ++k) {
      float* d = r.g[3 * g + k];
      for (int x = 0; x < w; ++x) d[x] = r.valid[x] > 0.0f ? d[x] : 0.0f;
    }
  }
  if (groups & kGuidePosition) {
    // kpos = log2e / (2 (footprint * sigma_pos_footprints)^2), 0 for a footprint that is not
    // positive and finite (as detail::position_coefficient).
    const float c = float(kLog2e / (2.0 * double(p.sigma_pos_footprints) * p.sigma_pos_footprints));
    if (in.footprint) {
      copy(in.footprint, r.kpos);
    } else {
      for (int x = 0; x < w; ++x) r.kpos[x] = p.footprint;
    }
    for (int x = 0; x < w; ++x) {
      const float fp = r.kpos[x];
      const bool ok = fp > 0.0f && fp - fp == 0.0f && r.valid[x] > 0.0f;
      r.kpos[x] = ok ? c / (fp * fp) : 0.0f;
    }
  }
}

}  // namespace

void cross_bilateral_fast(const GuidedInput& in, const FilterParams& p, float* out) {
  cross_bilateral_fast_counted(in, p, out, nullptr);
}

void cross_bilateral_fast_counted(const GuidedInput& in, const FilterParams& p, float* out, std::size_t* direct_pixels) {
  check_input(in, p);
  std::atomic<std::size_t> direct_count{0};
  const fast_isa::Kernels& kernels = fast_isa::best();
  const int lanes = kernels.width;
  const int w = in.width, h = in.height, s = fast_cell_size(p, in.width, in.height);
  const unsigned groups = p.groups;
  const bool pos = (groups & kGuidePosition) != 0;
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
  // The direct evaluation: the definition over the fine pixels of the cells within near_cells of
  // the pixel's cell, the nodes of the cells beyond, out to far_radius cells (its window of
  // direct_radius pixels).
  const int direct_radius = p.fast_direct_radius > 0 ? p.fast_direct_radius : fast_radius(p);
  const int far_radius = (direct_radius + s - 1) / s;
  const int near_cells = p.fast_direct_near > 0 ? std::min(far_radius, (p.fast_direct_near + s - 1) / s) : far_radius;
  const int pad = std::max(radius_nodes, far_radius) + 1;
  const int pitch = round_up(nw + 2 * pad + lanes + 1, lanes);
  const int rows = nh + 2 * pad;
  const std::size_t plane = std::size_t(pitch) * rows;
  // px, py, 9 guide, kpos, sum, mass, num, den
  // Kept between calls on this thread: a fresh 10 MB allocation per frame costs more in page
  // faults than the coarse filter itself.
  static thread_local std::vector<float> node_store;
  node_store.assign(16 * plane, 0.0f);
  // The pool's workers see their own (empty) thread_local: they reach the caller's through this.
  float* const node_base = node_store.data();
  auto node_plane = [&](int k) { return node_base + std::size_t(k) * plane; };
  float *npx = node_plane(0), *npy = node_plane(1), *nk = node_plane(11), *nsum = node_plane(12), *nmass = node_plane(13),
        *nnum = node_plane(14), *nden = node_plane(15);
  auto node_index = [&](int cx, int cy) { return std::size_t(cy + pad) * pitch + std::size_t(cx + pad); };
  const int fine_pitch = round_up(w, lanes) + lanes;
  const float kn1 = float(kLog2e * kn), ka1 = float(kLog2e * ka);
  auto row_buffers = [&](std::vector<float>& buf, int count) {
    buf.assign(std::size_t(fine_pitch) * 13 * count, 0.0f);
    std::vector<FineRow> r(count);
    for (int i = 0; i < count; ++i) {
      float* b0 = buf.data() + std::size_t(fine_pitch) * 13 * i;
      for (int k = 0; k < 9; ++k) r[i].g[k] = b0 + std::size_t(k) * fine_pitch;
      r[i].valid = b0 + std::size_t(9) * fine_pitch;
      r[i].lum = b0 + std::size_t(10) * fine_pitch;
      r[i].kpos = b0 + std::size_t(11) * fine_pitch;
    }
    return r;
  };
  parallel_rows(nh, [&](int64_t b, int64_t e) {
    std::vector<float> buf;
    const std::vector<FineRow> fr = row_buffers(buf, s);
    std::vector<float> weight(static_cast<std::size_t>(fine_pitch));
    for (int cy = int(b); cy < int(e); ++cy) {
      const int y0 = cy * s, y1 = std::min(h, y0 + s);
      for (int y = y0; y < y1; ++y) prepare_row(in, p, groups, y, fr[y - y0]);
      const std::size_t row0 = node_index(0, cy);
      // Representatives: the centre pixel, else the first valid pixel of the cell.
      for (int cx = 0; cx < nw; ++cx) {
        const int x0 = cx * s, x1 = std::min(w, x0 + s);
        int rx = std::min(x0 + s / 2, x1 - 1), ry = std::min(y0 + s / 2, y1 - 1);
        if (fr[ry - y0].valid[rx] == 0.0f) {
          rx = -1;
          for (int yy = y0; yy < y1 && rx < 0; ++yy)
            for (int xx = x0; xx < x1; ++xx)
              if (fr[yy - y0].valid[xx] > 0.0f) {
                rx = xx;
                ry = yy;
                break;
              }
        }
        const std::size_t n = row0 + cx;
        if (rx < 0) continue;  // no geometry in this cell: mass stays 0
        for (int k = 0; k < 9; ++k) node_plane(2 + k)[n] = fr[ry - y0].g[k][rx];
        nk[n] = fr[ry - y0].kpos[rx];  // unscaled for now (the gathering below uses it as is)
        nmass[n] = -1.0f;                // has a representative
      }
      const float* rep_g[9];
      for (int k = 0; k < 9; ++k) rep_g[k] = node_plane(2 + k) + row0;
      for (int y = y0; y < y1; ++y) {
        const FineRow& r = fr[y - y0];
        kernels.aggregate_row(groups, w, s, r.g, r.valid, rep_g, nk + row0, kn1, ka1, weight.data());
        for (int cx = 0; cx < nw; ++cx) {
          const std::size_t n = row0 + cx;
          if (nmass[n] == 0.0f) continue;
          float sum = 0.0f, mass = 0.0f, mx = 0.0f;
          for (int x = cx * s, x1 = std::min(w, cx * s + s); x < x1; ++x) {
            if (weight[x] == 0.0f) continue;  // invalid: its luminance may be NaN
            sum += weight[x] * r.lum[x];
            mass += weight[x];
            mx += weight[x] * float(x);
          }
          nsum[n] += sum;
          npx[n] += mx;
          npy[n] += mass * float(y);
          nnum[n] += mass;  // nnum is scratch for the mass until B
        }
      }
      for (int cx = 0; cx < nw; ++cx) {
        const std::size_t n = row0 + cx;
        if (nmass[n] == 0.0f) continue;
        const float mass = nnum[n];
        // The node sits at the centroid of what it gathered, so no half-pixel shift creeps in.
        npx[n] /= mass;
        npy[n] /= mass;
        nmass[n] = mass;
        nnum[n] = 0.0f;
        nk[n] /= float(rho2);
      }
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
  const float spatial_direct = float(-kLog2e / (2.0 * sg2));
  const float max_spread2 = p.fast_max_spread > 0 ? p.fast_max_spread * p.fast_max_spread : 1e30f;
  parallel_rows(h, [&](int64_t b, int64_t e) {
    std::vector<float> buf;
    const FineRow fr = row_buffers(buf, 1)[0];
    float* result = buf.data() + std::size_t(12) * fine_pitch;
    std::vector<float> need_buf(static_cast<std::size_t>(fine_pitch));
    float* need = need_buf.data();
    // The fine rows around y that the direct evaluation reads (those of the cell rows cy -
    // near_cells .. cy + near_cells), prepared on first use and kept in a ring of 2 near + 1 slots
    // (rows come in increasing order on this thread).
    const int near = (near_cells + 1) * s - 1;
    const int ring_size = 2 * near + 1;
    std::vector<float> ring_buf;
    std::vector<FineRow> ring;
    std::vector<int> ring_row;
    std::vector<fast_isa::RowPlanes> window(static_cast<std::size_t>(ring_size));
    auto prepare_window = [&](int y) {
      if (ring.empty()) {
        ring = row_buffers(ring_buf, ring_size);
        ring_row.assign(static_cast<std::size_t>(ring_size), -1);
      }
      for (int t = 0; t < ring_size; ++t) {
        const int yy = y - near + t;
        fast_isa::RowPlanes& r = window[std::size_t(t)];
        if (yy < 0 || yy >= h) {
          r = fast_isa::RowPlanes{};
          continue;
        }
        const std::size_t slot = std::size_t(yy % ring_size);
        if (ring_row[slot] != yy) {
          prepare_row(in, p, groups, yy, ring[slot]);
          ring_row[slot] = yy;
        }
        for (int k = 0; k < 9; ++k) r.g[k] = ring[slot].g[k];
        r.valid = ring[slot].valid;
        r.lum = ring[slot].lum;
      }
    };
    for (int y = int(b); y < int(e); ++y) {
      prepare_row(in, p, groups, y, fr);
      const int cy = y / s;
      const float* node_rows[3][14];
      for (int r = 0; r < 3; ++r) {
        const std::size_t row = node_index(0, cy - 1 + r);
        node_rows[r][0] = nnum + row;
        node_rows[r][1] = nden + row;
        node_rows[r][2] = npx + row;
        node_rows[r][3] = npy + row;
        for (int k = 0; k < 9; ++k) node_rows[r][4 + k] = node_plane(2 + k) + row;
        node_rows[r][13] = nmass + row;
      }
      kernels.upsample_row(groups, w, s, y, cy - 1, spatial_c, fr.g, fr.kpos, fr.lum, fr.valid, node_rows, kn1, ka1,
                           p.fast_min_weight, float(p.fast_ridge * s * s), max_spread2,
                           float(p.fast_min_node_mass * s * s), result, need);
      bool window_ready = false;
      // The near cells, never past the definition's window (they reach it when near_cells = far_radius).
      const int near_y0 = std::max({0, (cy - near_cells) * s, y - direct_radius});
      const int near_y1 = std::min({h - 1, (cy + near_cells + 1) * s - 1, y + direct_radius});
      for (int x = 0; x < w; ++x) {
        if (need[x] == 0.0f) continue;
        direct_count.fetch_add(1, std::memory_order_relaxed);
        if (!window_ready) prepare_window(y), window_ready = true;
        float cg[9];
        for (int k = 0; k < 9; ++k) cg[k] = fr.g[k][x];
        const int cx = x / s;
        const int near_x0 = std::max({0, (cx - near_cells) * s, x - direct_radius});
        const int near_x1 = std::min({w - 1, (cx + near_cells + 1) * s - 1, x + direct_radius});
        result[x] = kernels.direct_pixel(groups, x, y, near_x0, near_x1, near_y0, near_y1 - near_y0 + 1,
                                               window.data() + (near_y0 - (y - near)), np, int(node_index(cx, cy)),
                                               near_cells, far_radius, cg, fr.kpos[x], kn1, ka1, spatial_direct);
      }
      std::memcpy(out + std::size_t(y) * w, result, sizeof(float) * std::size_t(w));
    }
  });
  if (direct_pixels) *direct_pixels = direct_count.load();
}

}  // namespace cgtmo::filters
