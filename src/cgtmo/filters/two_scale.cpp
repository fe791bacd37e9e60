// `fast`: the cross-bilateral of guide.h evaluated at two scales.
//  A. Cells of s x s pixels. Each cell's representative is a real pixel, so its guide is never a
//     blend of two surfaces: the centre pixel, or the cell's medoid where the centre is in the
//     cell's minority (two_scale.majority). A node gathers the pixels within 1.5 cells of its cell's
//     centre with a quadratic B-spline weight (every pixel shared by the 3x3 nodes around it)
//     times the guide weight f(rep, y): a pixel of another surface weighs ~0 there (it is
//     described by the nodes of its own surface). The node sits at the weighted centroid of what
//     it gathered; its guide is its own cell's mean, weighted by f(rep, y).
//  B. The filter between representatives, in 2-D over a window of a few effective sigmas, with
//     num/den kept apart (homogeneous coordinates).
//  C. Each pixel x takes the num/den of the 2x2 representatives around it, weighted by a small
//     spatial Gaussian (sigma s/2) times f(x, rep): representatives of other surfaces drop out.
//     The pixel is evaluated by the definition instead (float, SIMD along the window rows, radius
//     fast_radius: 3 effective sigmas; the cells beyond two_scale.direct_near pixels enter through
//     their nodes, where the weight varies little across a cell) where the nodes cannot be trusted:
//       - their total weight for x is under two_scale.min_weight (a feature thinner than a cell, a
//         crease line of blended normals, an anti-aliased albedo edge), counting only nodes that
//         gathered at least two_scale.min_node_mass of their cell (a node on a strip thinner than a
//         cell has a coarse value no better than its few pixels) and whose cell's pixels keep
//         two_scale.min_purity of their weight in normal and albedo (a textured cell), or
//       - the pixel lies beyond the nodes that describe it (frame border, end of a surface), or
//       - their values spread by more than two_scale.max_spread (weighted standard deviation, log10):
//         they straddle a change of the signal that a plane through them would extrapolate.
//     Measured (docs/speed-vs-error.md): on the committed scenes nearly all of the two-scale
//     error sat within 3 pixels of a guide edge (normal, albedo), and on the worst (sun-window,
//     relief, night) the largest errors were anti-aliased edge pixels whose own guide is a blend
//     and thin strips narrower than a cell, where the nodes around them describe another surface.
// The blur that A and C add (the B-spline: s^2/4, upsampling ~ (s/2)^2) is taken out of B's sigmas, so
// the three stages together have the spatial variance of the definition. Cost per pixel:
// (2r+1)^2 / s^2 taps at B plus 9 at A and 4 at C, against (2R+1)^2 for the definition.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/simd_kernels.h"
#include "cgtmo/filters/guide.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::filters {

namespace {

using detail::kLog2e;
int round_up(int v, int m) { return (v + m - 1) / m * m; }

// One fine row as the kernels read it (detail::sanitize_row, position coefficient * log2 e),
// contiguous, padded to a multiple of the vector width.
using FineRow = detail::RowOut;

void prepare_row(const GuidedInput& in, const FilterParams& p, unsigned groups, int y, const FineRow& r) {
  detail::sanitize_row(in, p, groups, y, r, float(kLog2e));
}

}  // namespace

void cross_bilateral_fast(const GuidedInput& in, const FilterParams& p, float* out) {
  cross_bilateral_fast_counted(in, p, out, nullptr);
}

void cross_bilateral_fast_counted(const GuidedInput& in, const FilterParams& p, float* out, std::size_t* direct_pixels) {
  check_input(in, p);
  std::atomic<std::size_t> direct_count{0};
  const simd_kernels::Kernels& kernels = simd_kernels::best();
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
  const double rho2 = std::max(0.25, (eff2 - s * s / 4.0 - up2) / eff2);  // B's sigmas shrink by sqrt(rho2)
  const int radius_nodes = std::max(1, int(std::ceil(p.effective_window_sigmas * std::sqrt(eff2 * rho2) / s)));

  // ---- A: nodes ----
  const int nw = (w + s - 1) / s, nh = (h + s - 1) / s;
  // The direct evaluation: the definition over the fine pixels of the cells within near_cells of
  // the pixel's cell, the nodes of the cells beyond, out to far_radius cells (its window of
  // direct_radius pixels).
  const int direct_radius = p.two_scale.direct_radius > 0 ? p.two_scale.direct_radius : fast_radius(p);
  const int far_radius = (direct_radius + s - 1) / s;
  const int near_cells = p.two_scale.direct_near > 0 ? std::min(far_radius, (p.two_scale.direct_near + s - 1) / s) : far_radius;
  const int pad = std::max(radius_nodes, far_radius) + 1;
  const int pitch = round_up(nw + 2 * pad + lanes + 1, lanes);
  const int rows = nh + 2 * pad;
  const std::size_t plane = std::size_t(pitch) * rows;
  // px, py, 9 guide, kpos, sum, mass, num, den
  // Kept between calls on this thread: a fresh 10 MB allocation per frame costs more in page
  // faults than the coarse filter itself.
  static thread_local std::vector<float> node_store;
  node_store.assign(19 * plane, 0.0f);
  // The pool's workers see their own (empty) thread_local: they reach the caller's through this.
  float* const node_base = node_store.data();
  auto node_plane = [&](int k) { return node_base + std::size_t(k) * plane; };
  float *npx = node_plane(0), *npy = node_plane(1), *nk = node_plane(11), *nsum = node_plane(12), *nmass = node_plane(13),
        *nnum = node_plane(14), *nden = node_plane(15), *nbox_sum = node_plane(16), *nbox_mass = node_plane(17), *ntrust = node_plane(18);
  auto node_index = [&](int cx, int cy) { return std::size_t(cy + pad) * pitch + std::size_t(cx + pad); };
  const int fine_pitch = round_up(w, lanes) + lanes;
  const float kn1 = float(kLog2e * kn), ka1 = float(kLog2e * ka);
  auto row_buffers = [&](std::vector<float>& buf, int count) {
    buf.assign(std::size_t(fine_pitch) * 12 * count, 0.0f);
    std::vector<FineRow> r(count);
    for (int i = 0; i < count; ++i) {
      float* b0 = buf.data() + std::size_t(fine_pitch) * 12 * i;
      for (int k = 0; k < 9; ++k) r[i].g[k] = b0 + std::size_t(k) * fine_pitch;
      r[i].valid = b0 + std::size_t(9) * fine_pitch;
      r[i].lum = b0 + std::size_t(10) * fine_pitch;
      r[i].kpos = b0 + std::size_t(11) * fine_pitch;
    }
    return r;
  };
  // Representatives: the centre pixel (else the first valid pixel of the cell); where less than
  // two_scale.majority of the weight of the cell's valid pixels stays with it (the centre lies on a
  // crease, a strip, an anti-aliased edge), the cell's medoid, the pixel with the largest total
  // weight towards the others: a node then stands for its cell's majority surface, whose pixels it
  // gathers at full weight. Measured: docs/cgtmo.md section 9.
  // RepRow: one node row's representatives at node column 0 (9 guide planes, kpos unscaled,
  // has-representative 1 or 0), readable like the node planes (padded by `pad` on both sides).
  struct RepRow {
    float* plane[11];
  };
  auto choose_representatives = [&](int y0, int y1, const RepRow& dst, auto& fine_row, float* scratch) {
    auto set_rep = [&](int cx, const FineRow& r, int x) {
      for (int k = 0; k < 9; ++k) dst.plane[k][cx] = r.g[k][x];
      dst.plane[9][cx] = r.kpos[x];
      dst.plane[10][cx] = 1.0f;
    };
    for (int cx = 0; cx < nw; ++cx) {
      const int x0 = cx * s, x1 = std::min(w, x0 + s);
      int rx = std::min(x0 + s / 2, x1 - 1), ry = std::min(y0 + s / 2, y1 - 1);
      if (fine_row(ry).valid[rx] == 0.0f) {
        rx = -1;
        for (int yy = y0; yy < y1 && rx < 0; ++yy) {
          const FineRow& r = fine_row(yy);
          for (int xx = x0; xx < x1; ++xx)
            if (r.valid[xx] > 0.0f) {
              rx = xx;
              ry = yy;
              break;
            }
        }
      }
      if (rx >= 0) set_rep(cx, fine_row(ry), rx);  // else no geometry in this cell
    }
    if (p.two_scale.majority <= 0.0f) return;
    const std::size_t fp = std::size_t(fine_pitch);
    for (int y = y0; y < y1; ++y) {
      const FineRow& r = fine_row(y);
      kernels.aggregate_row(groups, w, s, r.g, r.valid, dst.plane, dst.plane[9], kn1, ka1, scratch + std::size_t(y - y0) * fp);
    }
    const FineRow* rows[8];
    for (int y = y0; y < y1; ++y) rows[y - y0] = &fine_row(y);
    for (int cx = 0; cx < nw; ++cx) {
      if (dst.plane[10][cx] == 0.0f) continue;
      const int x0 = cx * s, x1 = std::min(w, x0 + s);
      float support = 0.0f;
      int count = 0;
      int px[64], py[64];  // the cell's valid pixels
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          support += scratch[std::size_t(y - y0) * fp + x];
          if (rows[y - y0]->valid[x] > 0.0f) px[count] = x, py[count] = y - y0, ++count;
        }
      if (support >= p.two_scale.majority * float(count)) continue;
      // Total weight of each valid pixel towards the others (the position factor is the
      // representative's: f is not symmetric), each pair's squared distances computed once.
      float total[64];
      for (int i = 0; i < count; ++i) total[i] = 1.0f;
      for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j) {
          const FineRow &a = *rows[py[i]], &q = *rows[py[j]];
          float d2[3] = {0.0f, 0.0f, 0.0f};
          for (int g = 0; g < 3; ++g) {
            if (!(groups & (1u << g))) continue;
            for (int k = 0; k < 3; ++k) {
              const float d = a.g[3 * g + k][px[i]] - q.g[3 * g + k][px[j]];
              d2[g] += d * d;
            }
          }
          const float shared = kn1 * d2[1] + ka1 * d2[2];
          total[i] += repro::exp2(-(a.kpos[px[i]] * d2[0] + shared));
          total[j] += repro::exp2(-(q.kpos[px[j]] * d2[0] + shared));
        }
      float best = support;
      int chosen = -1;
      for (int i = 0; i < count; ++i)
        if (total[i] > best * 1.001f) best = total[i], chosen = i;
      if (chosen >= 0) set_rep(cx, *rows[py[chosen]], px[chosen]);
    }
  };
  // A node gathers the pixels within 1.5 cells of its cell's centre, weighted by a quadratic
  // B-spline of the distance (a partition of unity over the nodes: every pixel is shared by the 3x3
  // nodes around it) times f(rep, y). A box gather (each pixel to its own cell's node) made the
  // stages' kernel a staircase across cell borders; on Monte Carlo noise that left errors of about
  // 1% of the noise (measured: docs/cgtmo.md section 9). With two_scale.share, a pixel's share of the
  // nodes of another surface around it goes to those of its own (share_row in simd_kernels.inc).
  const double centre_off = (s - 1) / 2.0, half = 1.5 * s;
  auto spline = [&](double d) {
    const double u = std::fabs(d) / s;
    return u < 0.5 ? 0.75 - u * u : u < 1.5 ? 0.5 * (1.5 - u) * (1.5 - u) : 0.0;
  };
  // spline_x[k + 1][x]: the weight of pixel x towards the centre of cell x / s + k.
  std::vector<float> spline_x(std::size_t(3) * fine_pitch);
  for (int k = -1; k <= 1; ++k)
    for (int x = 0; x < fine_pitch; ++x)
      spline_x[std::size_t(k + 1) * fine_pitch + x] = float(spline(x % s - centre_off - k * s));
  const bool share = p.two_scale.share > 0.0f;
  const float share_relax = 1.0f / 16.0f, share_log_ratio = share ? float(-repro::log2(double(p.two_scale.share))) : 0.0f;
  parallel_rows(nh, [&](int64_t b, int64_t e) {
    // Prepared fine rows in a ring (node rows come in increasing order on this thread and share
    // most of the rows they read): the supports of node row cy and the cells of node rows up to
    // cy + 2, with each row's share_row result once computed.
    const int ring_size = 5 * s + 2;
    const std::size_t fp = std::size_t(fine_pitch);
    std::vector<float> buf, share_buf(std::size_t(2 * ring_size) * fp);
    const std::vector<FineRow> ring = row_buffers(buf, ring_size);
    std::vector<int> ring_row(static_cast<std::size_t>(ring_size), -1), share_of_slot(ring_row.size(), -1);
    auto slot_of = [&](int y) { return std::size_t(y % ring_size); };
    auto fine_row = [&](int y) -> const FineRow& {
      const std::size_t slot = slot_of(y);
      if (ring_row[slot] != y) prepare_row(in, p, groups, y, ring[slot]), ring_row[slot] = y;
      return ring[slot];
    };
    // The representatives of node rows cy - 2 .. cy + 2 in a ring of 5, chosen on this thread
    // (bands overlap: neighbouring threads choose the same ones for themselves), and an empty row
    // for the rows outside the frame.
    const int rep_slots = 6;
    std::vector<float> rep_buf(std::size_t(rep_slots) * 11 * pitch, 0.0f), scratch(std::size_t(s) * fp);
    std::vector<int> rep_row(static_cast<std::size_t>(rep_slots), -1);
    auto rep_at = [&](int slot) {
      RepRow r;
      for (int k = 0; k < 11; ++k) r.plane[k] = rep_buf.data() + (std::size_t(slot) * 11 + k) * pitch + pad;
      return r;
    };
    auto reps = [&](int cy) {
      if (cy < 0 || cy >= nh) return rep_at(rep_slots - 1);  // stays empty
      const int slot = cy % (rep_slots - 1);
      const RepRow r = rep_at(slot);
      if (rep_row[std::size_t(slot)] != cy) {
        std::fill(rep_buf.begin() + std::ptrdiff_t(std::size_t(slot) * 11 * pitch),
                  rep_buf.begin() + std::ptrdiff_t(std::size_t(slot + 1) * 11 * pitch), 0.0f);
        choose_representatives(cy * s, std::min(h, cy * s + s), r, fine_row, scratch.data());
        rep_row[std::size_t(slot)] = cy;
      }
      return r;
    };
    // Per pixel, summed over the support rows: for k = -1, 0, 1 (towards the node of cell
    // x / s + k) the weight, weight x log luminance and weight x y; and the box sums of the
    // node row's own cells (weight, 9 guide channels, log luminance).
    std::vector<float> acc(std::size_t(22) * fp);
    float* acc_rows[9];
    float* box_rows[13];
    for (int i = 0; i < 9; ++i) acc_rows[i] = acc.data() + std::size_t(i) * fp;
    for (int i = 0; i < 13; ++i) box_rows[i] = acc.data() + std::size_t(9 + i) * fp;
    const float* spline_rows[3];
    for (int k = 0; k < 3; ++k) spline_rows[k] = spline_x.data() + std::size_t(k) * fp;
    for (int cy = int(b); cy < int(e); ++cy) {
      const int y0 = cy * s, y1 = std::min(h, y0 + s);
      const double cyc = y0 + centre_off;
      const int ya = std::max(0, int(std::floor(cyc - half)) + 1), yb = std::min(h - 1, int(std::ceil(cyc + half)) - 1);
      const std::size_t row0 = node_index(0, cy);
      RepRow around[5];
      for (int r = 0; r < 5; ++r) around[r] = reps(cy - 2 + r);
      const RepRow& own = around[2];
      std::fill(acc.begin(), acc.end(), 0.0f);
      for (int y = ya; y <= yb; ++y) {
        const float tv = float(spline(y - cyc));
        if (tv <= 0.0f) continue;
        const FineRow& r = fine_row(y);
        simd_kernels::ShareRow share_of_row{nullptr, nullptr, share_relax};
        if (share) {
          const std::size_t slot = slot_of(y);
          float* factor = share_buf.data() + 2 * slot * fp;
          float* limit = factor + fp;
          if (share_of_slot[slot] != y) {
            const int cell_row = y / s;  // node rows cell_row - 1 .. + 1, in around[] at cell_row - cy + 1 ..
            const float* rows[3][11];
            float sy[3];
            for (int k = 0; k < 3; ++k) {
              const RepRow& rr = around[cell_row - 1 + k - (cy - 2)];
              for (int ch = 0; ch < 11; ++ch) rows[k][ch] = rr.plane[ch];
              sy[k] = float(spline(y - ((cell_row - 1 + k) * s + centre_off)));
            }
            kernels.share_row(groups, w, s, r.g, r.valid, rows, sy, spline_rows, kn1, ka1, share_relax, share_log_ratio,
                              factor, limit);
            share_of_slot[slot] = y;
          }
          share_of_row.factor = factor;
          share_of_row.limit = limit;
        }
        const bool own_row = y >= y0 && y < y1;
        kernels.gather_row(groups, w, s, r.g, r.valid, r.lum, own.plane, own.plane[9], kn1, ka1, tv, float(y), spline_rows,
                           share_of_row, acc_rows, own_row ? box_rows : nullptr);
      }
      for (int cx = 0; cx < nw; ++cx) {
        const std::size_t n = row0 + cx;
        if (own.plane[10][cx] == 0.0f) continue;  // no geometry in this cell: mass stays 0
        float mass = 0.0f, sum = 0.0f, mx = 0.0f, my = 0.0f;
        for (int k = -1; k <= 1; ++k) {
          const int from = cx - k;  // the cell whose pixels reach this node through k
          if (from < 0 || from >= nw) continue;
          const float *m = acc_rows[3 * (k + 1)], *sl = m + fp, *yy = sl + fp;
          for (int x = from * s, x1 = std::min(w, from * s + s); x < x1; ++x) {
            mass += m[x];
            sum += sl[x];
            mx += m[x] * float(x);
            my += yy[x];
          }
        }
        if (!(mass > 0.0f)) continue;  // (the representative itself always reaches its node)
        float box = 0.0f, box_sum = 0.0f, same_range = 0.0f, valid = 0.0f;
        for (int x = cx * s, x1 = std::min(w, cx * s + s); x < x1; ++x) {
          box += box_rows[0][x];
          box_sum += box_rows[10][x];
          same_range += box_rows[11][x];
          valid += box_rows[12][x];
        }
        nbox_sum[n] = box_sum;
        nbox_mass[n] = box;
        // Trusted by the upsampling (its mass as a fraction of the cell) unless its cell's pixels
        // keep less than two_scale.min_purity of their weight towards the representative in normal and
        // albedo: a textured cell (bricks and mortar, bump-mapped bevels) stands for a mixture
        // whose coarse value does not follow the guide of each of its pixels.
        ntrust[n] = same_range >= p.two_scale.min_purity * valid ? mass / float(s * s) : 0.0f;
        // The node sits at the centroid of what it gathered, so no half-pixel shift creeps in.
        npx[n] = mx / mass;
        npy[n] = my / mass;
        nsum[n] = sum;
        nmass[n] = mass;
        nk[n] = own.plane[9][cx] / float(rho2);
        // Its guide: the mean of its own cell's pixels, weighted by their similarity to the
        // representative (a cell's pixels vary around it: texture, bumps, noise in the guide).
        for (int ch = 0; ch < 9; ++ch) {
          if (!(groups & (1u << (ch / 3)))) continue;
          const float* gs = box_rows[1 + ch];
          float g = 0.0f;
          for (int x = cx * s, x1 = std::min(w, cx * s + s); x < x1; ++x) g += gs[x];
          node_plane(2 + ch)[n] = g / box;
        }
      }
    }
  });

  // ---- B: between nodes ----
  simd_kernels::NodePlanes np{};
  np.px = npx;
  np.py = npy;
  for (int k = 0; k < 9; ++k) np.g[k] = node_plane(2 + k);
  np.kpos = nk;
  np.sum = nsum;
  np.mass = nmass;
  np.pitch = pitch;
  // The direct evaluation's far cells: what each node gathered from its own cell (box), since its
  // near cells are summed pixel by pixel and a B-spline node would count their border pixels twice.
  simd_kernels::NodePlanes np_cells = np;
  np_cells.sum = nbox_sum;
  np_cells.mass = nbox_mass;
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
  const float max_spread2 = p.two_scale.max_spread > 0 ? p.two_scale.max_spread * p.two_scale.max_spread : 1e30f;
  parallel_rows(h, [&](int64_t b, int64_t e) {
    std::vector<float> result_buf(static_cast<std::size_t>(fine_pitch)), need_buf(result_buf.size());
    float *result = result_buf.data(), *need = need_buf.data();
    // The fine rows around y that the direct evaluation reads (those of the cell rows cy -
    // near_cells .. cy + near_cells) and row y itself, prepared on first use and kept in a ring of
    // 2 near + 1 slots (rows come in increasing order on this thread).
    const int near = (near_cells + 1) * s - 1;
    const int ring_size = 2 * near + 1;
    std::vector<float> ring_buf;
    const std::vector<FineRow> ring = row_buffers(ring_buf, ring_size);
    std::vector<int> ring_row(static_cast<std::size_t>(ring_size), -1);
    auto fine_row = [&](int yy) -> const FineRow& {
      const std::size_t slot = std::size_t(yy % ring_size);
      if (ring_row[slot] != yy) prepare_row(in, p, groups, yy, ring[slot]), ring_row[slot] = yy;
      return ring[slot];
    };
    std::vector<simd_kernels::RowPlanes> window(static_cast<std::size_t>(ring_size));
    auto prepare_window = [&](int y) {
      for (int t = 0; t < ring_size; ++t) {
        const int yy = y - near + t;
        simd_kernels::RowPlanes& r = window[std::size_t(t)];
        if (yy < 0 || yy >= h) {
          r = simd_kernels::RowPlanes{};
          continue;
        }
        const FineRow& f = fine_row(yy);
        for (int k = 0; k < 9; ++k) r.g[k] = f.g[k];
        r.valid = f.valid;
        r.lum = f.lum;
      }
    };
    for (int y = int(b); y < int(e); ++y) {
      const FineRow& fr = fine_row(y);
      const int cy = y / s;
      const float* node_rows[3][14];
      for (int r = 0; r < 3; ++r) {
        const std::size_t row = node_index(0, cy - 1 + r);
        node_rows[r][0] = nnum + row;
        node_rows[r][1] = nden + row;
        node_rows[r][2] = npx + row;
        node_rows[r][3] = npy + row;
        for (int k = 0; k < 9; ++k) node_rows[r][4 + k] = node_plane(2 + k) + row;
        node_rows[r][13] = ntrust + row;
      }
      kernels.upsample_row(groups, w, s, y, cy - 1, spatial_c, fr.g, fr.kpos, fr.lum, fr.valid, node_rows, kn1, ka1,
                           p.two_scale.min_weight, float(p.two_scale.ridge * s * s), max_spread2,
                           p.two_scale.min_node_mass, result, need);
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
                                               window.data() + (near_y0 - (y - near)), np_cells, int(node_index(cx, cy)),
                                               near_cells, far_radius, cg, fr.kpos[x], kn1, ka1, spatial_direct);
      }
      // Background keeps its input (guide.h); the prepared row holds 0 there.
      for (int x = 0; x < w; ++x)
        if (fr.valid[x] == 0.0f) result[x] = in.log_lum[std::size_t(y) * w + x];
      std::memcpy(out + std::size_t(y) * w, result, sizeof(float) * std::size_t(w));
    }
  });
  if (direct_pixels) *direct_pixels = direct_count.load();
}

}  // namespace cgtmo::filters
