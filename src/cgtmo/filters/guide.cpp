#include "cgtmo/filters/guide.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cgtmo/errors.h"
#include "cgtmo/filters/detail.h"
#include "cgtmo/filters/simd_kernels.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::filters {

std::string describe_groups(unsigned groups) {
  std::string s;
  const char* names[3] = {"position", "normal", "albedo"};
  for (int g = 0; g < 3; ++g)
    if (groups & (1u << g)) s += (s.empty() ? "" : "+") + std::string(names[g]);
  return s.empty() ? "none" : s;
}

void check_input(const GuidedInput& in, const FilterParams& p) {
  if (in.width <= 0 || in.height <= 0) throw UsageError("filter: empty frame");
  if (!in.log_lum) throw UsageError("filter: no log-luminance channel");
  if (p.groups & ~unsigned(kGuideAll)) throw UsageError("filter: unknown guide group bits");
  auto need3 = [&](const Channel* c, const char* what) {
    for (int k = 0; k < 3; ++k)
      if (!c[k]) throw UsageError(std::string("filter: the ") + what + " group is active but its channels are missing");
  };
  if (p.groups & kGuidePosition) {
    need3(in.position, "position");
    if (!in.footprint && !(p.footprint > 0.0f))
      throw UsageError("filter: the position group needs a footprint (plane or FilterParams::footprint > 0)");
    if (!(p.sigma_pos_footprints > 0.0f)) throw UsageError("filter: sigma_pos_footprints must be positive");
  }
  if (p.groups & kGuideNormal) {
    need3(in.normal, "normal");
    if (!(p.sigma_normal > 0.0f)) throw UsageError("filter: sigma_normal must be positive");
  }
  if (p.groups & kGuideAlbedo) {
    need3(in.albedo, "albedo");
    if (!(p.sigma_albedo > 0.0f)) throw UsageError("filter: sigma_albedo must be positive");
  }
  if (!(p.sigma_spatial_px > 0.0f) || !std::isfinite(p.sigma_spatial_px))
    throw UsageError("filter: sigma_spatial_px must be positive");
  if (!(p.window_sigmas > 0.0f) || p.window_sigmas > 10.0f) throw UsageError("filter: window_sigmas must be in (0, 10]");
  if (p.poisson_samples < 1 || p.poisson_samples > 4096) throw UsageError("filter: poisson_samples must be in [1, 4096]");
  if (!(p.sigma_range_log10 > 0.0f)) throw UsageError("filter: sigma_range_log10 must be positive");
  if (!(p.effective_window_sigmas > 0.0f) || p.effective_window_sigmas > 10.0f)
    throw UsageError("filter: effective_window_sigmas must be in (0, 10]");
  if (p.two_scale.cell_size != 0 && (p.two_scale.cell_size < 2 || p.two_scale.cell_size > 8))
    throw UsageError("filter: two_scale.cell_size must be 0 (automatic) or in [2, 8]");
  if (!(p.two_scale.min_weight >= 0.0f) || p.two_scale.min_weight > 100.0f)
    throw UsageError("filter: two_scale.min_weight must be in [0, 100]");
  if (p.two_scale.direct_radius < 0 || p.two_scale.direct_radius > 64) throw UsageError("filter: two_scale.direct_radius must be in [0, 64]");
  if (p.two_scale.direct_near < 0 || p.two_scale.direct_near > 64) throw UsageError("filter: two_scale.direct_near must be in [0, 64]");
  if (!(p.two_scale.ridge >= 0.0f) || !std::isfinite(p.two_scale.ridge)) throw UsageError("filter: two_scale.ridge must be finite and >= 0");
  if (!(p.two_scale.max_spread >= 0.0f) || !std::isfinite(p.two_scale.max_spread))
    throw UsageError("filter: two_scale.max_spread must be finite and >= 0");
  if (!(p.two_scale.min_node_mass >= 0.0f) || p.two_scale.min_node_mass > 1.0f)
    throw UsageError("filter: two_scale.min_node_mass must be in [0, 1]");
  if (!(p.two_scale.min_purity >= 0.0f) || p.two_scale.min_purity > 1.0f) throw UsageError("filter: two_scale.min_purity must be in [0, 1]");
  if (!(p.two_scale.majority >= 0.0f) || p.two_scale.majority > 1.0f) throw UsageError("filter: two_scale.majority must be in [0, 1]");
  if (!(p.two_scale.share >= 0.0f) || p.two_scale.share >= 1.0f) throw UsageError("filter: two_scale.share must be in [0, 1)");
}

int fast_cell_size(const FilterParams& p, int width, int height) {
  (void)width, (void)height;
  return p.two_scale.cell_size != 0 ? p.two_scale.cell_size : 3;
}

namespace detail {

namespace {

// dst[x] = the channel at x of the row.
void load_channel(const Channel& c, std::size_t row, int w, float* dst) {
  const float* s = c.data + row * std::size_t(c.stride);
  if (c.stride == 1) {
    std::memcpy(dst, s, sizeof(float) * std::size_t(w));
    return;
  }
  const std::size_t st = std::size_t(c.stride);
  for (int x = 0; x < w; ++x) dst[x] = s[std::size_t(x) * st];
}

// valid[x] = 0 where d[x] is not finite (v - v is 0 for finite v and NaN otherwise: a test that
// vectorises).
void and_finite(const float* d, int w, float* valid) {
  for (int x = 0; x < w; ++x) valid[x] = d[x] - d[x] == 0.0f ? valid[x] : 0.0f;
}

// dst[k][x] = channel k of the row, and valid[x] = 0 where any of the three is not finite. An
// interleaved triple (RGB of one buffer: the renders' passes) is read in one pass.
void load_triple(const Channel* c, std::size_t row, int w, float* const dst[3], float* valid) {
  if (c[0].stride == 3 && c[1].stride == 3 && c[2].stride == 3 && c[1].data == c[0].data + 1 && c[2].data == c[0].data + 2) {
    simd_kernels::best().split_triples(c[0].data + row * 3, w, dst[0], dst[1], dst[2], valid);
    return;
  }
  for (int k = 0; k < 3; ++k) {
    load_channel(c[k], row, w, dst[k]);
    and_finite(dst[k], w, valid);
  }
}

}  // namespace

void sanitize_row(const GuidedInput& in, const FilterParams& p, unsigned groups, int y, const RowOut& r, float kpos_scale) {
  const int w = in.width;
  const std::size_t row = std::size_t(y) * std::size_t(w);
  float* valid = r.valid;
  if (in.mask) {
    load_channel(in.mask, row, w, valid);
    for (int x = 0; x < w; ++x) valid[x] = valid[x] > 0.5f ? 1.0f : 0.0f;
  } else {
    for (int x = 0; x < w; ++x) valid[x] = 1.0f;
  }
  load_channel(in.log_lum, row, w, r.lum);
  and_finite(r.lum, w, valid);
  const Channel* src[3] = {in.position, in.normal, in.albedo};
  for (int g = 0; g < 3; ++g)
    if (groups & (1u << g)) load_triple(src[g], row, w, r.g + 3 * g, valid);
  // Zeros where invalid (only rows that have such pixels: most have none).
  float invalid = 0.0f;
  for (int x = 0; x < w; ++x) invalid += 1.0f - valid[x];
  if (invalid > 0.0f) {
    for (int x = 0; x < w; ++x) r.lum[x] = valid[x] > 0.0f ? r.lum[x] : 0.0f;
    for (int k = 0; k < 9; ++k)
      if (groups & (1u << (k / 3)))
        for (int x = 0; x < w; ++x) r.g[k][x] = valid[x] > 0.0f ? r.g[k][x] : 0.0f;
  }
  if (groups & kGuidePosition) {
    // kpos_scale / (2 (footprint * sigma_pos_footprints)^2), 0 for a footprint that is not positive
    // and finite (position_coefficient).
    const float c = float(double(kpos_scale) / (2.0 * double(p.sigma_pos_footprints) * p.sigma_pos_footprints));
    if (in.footprint)
      load_channel(in.footprint, row, w, r.kpos);
    else
      for (int x = 0; x < w; ++x) r.kpos[x] = p.footprint;
    for (int x = 0; x < w; ++x) {
      const float fp = r.kpos[x];
      const bool ok = fp > 0.0f && fp - fp == 0.0f && valid[x] > 0.0f;
      r.kpos[x] = ok ? c / (fp * fp) : 0.0f;
    }
  }
}

PlanarFrame make_planar(const GuidedInput& in, const FilterParams& p, bool with_guide) {
  PlanarFrame f;
  f.width = in.width;
  f.height = in.height;
  const std::size_t n = in.pixel_count();
  const unsigned groups = with_guide ? p.groups : 0u;
  f.lum.allocate(n);
  f.valid.allocate(n);
  if (groups & kGuidePosition) f.kpos.allocate(n);
  for (int g = 0; g < 3; ++g)
    if (groups & (1u << g))
      for (int k = 0; k < 3; ++k) f.guide[3 * g + k].allocate(n);
  // Row by row, each element written once, on the thread that will mostly read it.
  detail::for_each_row(in.height, [&](int y) {
    const std::size_t b = std::size_t(y) * in.width;
    RowOut r{};
    for (int k = 0; k < 9; ++k)
      if (groups & (1u << (k / 3))) r.g[k] = f.guide[k].data() + b;
    r.valid = f.valid.data() + b;
    r.lum = f.lum.data() + b;
    r.kpos = (groups & kGuidePosition) ? f.kpos.data() + b : nullptr;
    sanitize_row(in, p, groups, y, r, 1.0f);
  });
  return f;
}

}  // namespace detail

GuideAnalysis analyze_guide(const GuidedInput& in, const FilterParams& p, float relative_threshold) {
  GuideAnalysis a;
  const std::size_t n = in.pixel_count();
  const Channel* src[3] = {in.position, in.normal, in.albedo};
  const char* names[3] = {"position", "normal", "albedo"};
  std::vector<float> sigma_pos;
  float lo[9], hi[9];
  std::fill(lo, lo + 9, std::numeric_limits<float>::infinity());
  std::fill(hi, hi + 9, -std::numeric_limits<float>::infinity());
  std::size_t valid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!detail::pixel_valid(in, 0u, i)) continue;
    bool present[3];
    for (int g = 0; g < 3; ++g) present[g] = src[g][0] && detail::finite3(src[g], i);
    ++valid;
    for (int g = 0; g < 3; ++g)
      if (present[g])
        for (int k = 0; k < 3; ++k) {
          lo[3 * g + k] = std::min(lo[3 * g + k], src[g][k][i]);
          hi[3 * g + k] = std::max(hi[3 * g + k], src[g][k][i]);
        }
    if (present[0]) {
      const double c = detail::position_coefficient(in, p, i);
      if (c > 0.0) sigma_pos.push_back(float(std::sqrt(1.0 / (2.0 * c))));
    }
  }
  if (!sigma_pos.empty()) {
    std::nth_element(sigma_pos.begin(), sigma_pos.begin() + sigma_pos.size() / 2, sigma_pos.end());
    a.sigma[0] = sigma_pos[sigma_pos.size() / 2];
  }
  a.sigma[1] = p.sigma_normal;
  a.sigma[2] = p.sigma_albedo;
  std::ostringstream ex;
  for (int g = 0; g < 3; ++g) {
    float spread = 0.0f;
    for (int k = 0; k < 3; ++k) spread = std::max(spread, hi[3 * g + k] - lo[3 * g + k]);
    a.spread[g] = valid ? spread : 0.0f;
    ex << names[g] << ": ";
    if (!src[g][0]) {
      ex << "dropped (no " << names[g] << " channels)\n";
    } else if (!(p.groups & (1u << g))) {
      ex << "dropped (switched off)\n";
    } else if (g == 0 && !(a.sigma[0] > 0.0f)) {
      ex << "dropped (no usable pixel footprint)\n";
    } else if (!(a.spread[g] >= relative_threshold * a.sigma[g])) {
      ex << "dropped (spread " << a.spread[g] << " < " << relative_threshold << " x sigma " << a.sigma[g]
         << ": every weight would be above " << repro::exp(-1.5 * relative_threshold * relative_threshold) << ")\n";
    } else {
      a.informative |= 1u << g;
      ex << "kept (spread " << a.spread[g] << ", sigma " << a.sigma[g] << ")\n";
    }
  }
  a.explain = ex.str();
  return a;
}

std::vector<float> footprint_from_positions(const GuidedInput& in) {
  const int w = in.width, h = in.height;
  std::vector<float> fp(in.pixel_count(), 0.0f);
  if (!in.position[0] || !in.position[1] || !in.position[2]) return fp;
  auto ok = [&](int x, int y) { return detail::pixel_valid(in, kGuidePosition, std::size_t(y) * w + x); };
  auto dist = [&](std::size_t a, std::size_t b) {
    const double dx = in.position[0][a] - in.position[0][b], dy = in.position[1][a] - in.position[1][b],
                 dz = in.position[2][a] - in.position[2][b];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  };
  detail::for_each_row(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (!ok(x, y)) continue;
      const std::size_t i = std::size_t(y) * w + x;
      double best = std::numeric_limits<double>::infinity();
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k)
        if (nx[k] >= 0 && nx[k] < w && ny[k] >= 0 && ny[k] < h && ok(nx[k], ny[k])) {
          const double d = dist(i, std::size_t(ny[k]) * w + nx[k]);
          if (d > 0.0) best = std::min(best, d);
        }
      fp[i] = std::isfinite(best) ? float(best) : 0.0f;
    }
  });
  // Pixels without a usable neighbour take the median of the others.
  std::vector<float> known;
  for (float v : fp)
    if (v > 0.0f) known.push_back(v);
  if (known.empty()) return fp;
  std::nth_element(known.begin(), known.begin() + known.size() / 2, known.end());
  const float median = known[known.size() / 2];
  for (std::size_t i = 0; i < fp.size(); ++i)
    if (!(fp[i] > 0.0f) && detail::pixel_valid(in, kGuidePosition, i)) fp[i] = median;
  return fp;
}

double rmse_valid(const float* a, const float* b, const GuidedInput& in) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0, n = in.pixel_count(); i < n; ++i) {
    if (in.mask && !(in.mask[i] > 0.5f)) continue;
    const double d = double(a[i]) - double(b[i]);
    sum += d * d;
    ++count;
  }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

}  // namespace cgtmo::filters
