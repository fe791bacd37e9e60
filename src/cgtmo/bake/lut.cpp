#include "cgtmo/bake/lut.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cgtmo/bake/audit.h"
#include "cgtmo/color/luminance.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::bake {

double Log2Shaper::forward(double x) const {
  const double l = repro::log2(std::max(x, 0.0) + std::ldexp(1.0, lo));
  return (l - lo) / double(hi - lo);
}

double Log2Shaper::inverse(double s) const {
  return repro::exp2(lo + s * double(hi - lo)) - std::ldexp(1.0, lo);
}

OCIO::TransformRcPtr range_clamp(double lo, double hi) {
  auto t = OCIO::RangeTransform::Create();
  t->setStyle(OCIO::RANGE_CLAMP);
  t->setMinInValue(lo);
  t->setMinOutValue(lo);
  t->setMaxInValue(hi);
  t->setMaxOutValue(hi);
  return t;
}

// The per-channel sides that OCIO's LogAffine and LogCamera transforms share, in base 2:
// y = log_slope * log2(lin_slope * x + lin_offset) + log_offset (LogCamera adds its linear
// segment below the break).
struct Log2Sides {
  double lin_slope[3], lin_offset[3], log_slope[3], log_offset[3];
};

template <class TransformPtr>
TransformPtr with_log2_sides(TransformPtr t, const Log2Sides& s, OCIO::TransformDirection dir = OCIO::TRANSFORM_DIR_FORWARD) {
  t->setBase(2.0);
  t->setLinSideSlopeValue(s.lin_slope);
  t->setLinSideOffsetValue(s.lin_offset);
  t->setLogSideSlopeValue(s.log_slope);
  t->setLogSideOffsetValue(s.log_offset);
  t->setDirection(dir);
  return t;
}

OCIO::TransformRcPtr Log2Shaper::transform(OCIO::TransformDirection dir) const {
  const double o = std::ldexp(1.0, lo), k = 1.0 / double(hi - lo);
  return with_log2_sides(OCIO::LogAffineTransform::Create(), {{1, 1, 1}, {o, o, o}, {k, k, k}, {-lo * k, -lo * k, -lo * k}}, dir);
}

std::string Log2Shaper::describe() const {
  std::ostringstream s;
  s << "log2 [" << lo << ", " << hi << "]";
  return s.str();
}

std::string Representation::describe() const {
  std::ostringstream s;
  s << dims << "D " << size;
  if (dims == 3) s << "^3";
  if (luminance) s << " on Y (xyY)";
  if (hue_steps) {
    s << " x4 in HSV (hue kept), log2(x+2^-24) over [-24, 17]";
    return s.str();
  }
  s << ", " << shaper.describe();
  if (warped) s << " -> per-channel node warp (1D " << warp_size << ")";
  if (dims == 3) s << ", out log2(y+2^" << out_log2 << ")";
  return s.str();
}

std::string Representation::extension() const { return hue_steps || warped ? ".ctf" : dims == 1 ? ".spi1d" : ".spi3d"; }

namespace {

// Clamps to [0, 65504] before the luminance design: negatives, NaN and values above the half
// maximum as cgtmo apply's sanitising (scene/sanitize.h) treats them.
OCIO::TransformRcPtr clamp_input() { return range_clamp(0.0, 65504.0); }

OCIO::TransformRcPtr xyy(OCIO::TransformDirection dir) {
  auto t = OCIO::FixedFunctionTransform::Create(OCIO::FIXED_FUNCTION_XYZ_TO_xyY);
  t->setDirection(dir);
  return t;
}

// The shaper of the luminance design, on Y only: the Log2Shaper formula on the third channel,
// the identity on the chromaticity channels (a LogCameraTransform's linear segment below its
// break at 2, slope 1 and offset 0; x and y lie in [0, 1]). A log on x and y would cost their
// exactness: the decode of a fast log and a LUT is off by about 1e-6, which saturated colours
// scaled far above 1 turn into code values.
OCIO::TransformRcPtr luminance_shaper(const Log2Shaper& s) {
  const double brk[3] = {2.0, 2.0, 0.0};
  const double ln2 = repro::log(2.0), k = 1.0 / double(s.hi - s.lo);
  // Identity below the break b: log side slope b ln 2 and offset b - b ln2 log2(b) make the
  // linear segment y = x.
  return with_log2_sides(OCIO::LogCameraTransform::Create(brk),
                         {{1, 1, 1}, {0, 0, std::ldexp(1.0, s.lo)}, {2 * ln2, 2 * ln2, k}, {2 - 2 * ln2, 2 - 2 * ln2, -s.lo * k}});
}

// The hue design (Representation::hue_steps). After RGB_TO_HSV the chain keeps H in channel 1
// untouched (identity LUT columns, LogCamera linear segments) and works on two linear quantities
// at a time in channels 2 and 3, through log2(x + 2^-24) encodings and matrices:
//   (H, S, V) -> (H, m, V) with m = V (1 - S) the minimum channel -> (H, m, delta = V - m)
//   -> toe: (H, toe(m), delta) -> (H, V' = toe(m) + delta, delta): the offset step.
//   -> (H, a = log2 V', b = log2 delta) -> (H, U(a), b) with U = log2 R + 3 a,
//      R(p) = shoulder(p) desaturation(p) / p -> (H, U, b + U) -> (H, a, b + U) -> (H, a, b + log2 R)
//   -> (H, log2 shoulder(V'), log2 S'') with S'' = delta R / shoulder = saturation after both steps
//   -> swap -> HSV_TO_RGB. U is increasing (hue_steps_apply checks it), so its LUT can be inverted.
constexpr double kHueEps = 1.0 / 16777216.0;  // 2^-24: the offset of every log2 encoding
constexpr double kHueLogLo = -24, kHueLogHi = 17;
constexpr double kHueKappa = 3;

double hue_ratio(const operators::HueKeepingSteps& st, double p) {
  p = std::max(p, 1e-30);
  return st.shoulder(p) * st.desaturation(p) / p;
}

double hue_u(const operators::HueKeepingSteps& st, double a) {
  return repro::log2(hue_ratio(st, std::max(repro::exp2(a) - kHueEps, 0.0))) + kHueKappa * a;
}

// Per channel: log2(x + 2^-24) on channels 2 and 3 (offset `eps3` on channel 3), identity on 1.
OCIO::TransformRcPtr hue_logs(OCIO::TransformDirection dir, double eps3 = kHueEps) {
  const double brk[3] = {2.0, 0.0, 0.0};
  const double ln2 = repro::log(2.0);
  return with_log2_sides(OCIO::LogCameraTransform::Create(brk), {{1, 1, 1}, {0, kHueEps, eps3}, {2 * ln2, 1, 1}, {2 - 2 * ln2, 0, 0}}, dir);
}

// A matrix on channels 2 and 3 (channel 1 kept), with offsets.
OCIO::TransformRcPtr hue_matrix(double m11, double m12, double m21, double m22, double o1 = 0, double o2 = 0) {
  auto t = OCIO::MatrixTransform::Create();
  const double v[16] = {1, 0, 0, 0, 0, m11, m12, 0, 0, m21, m22, 0, 0, 0, 0, 1};
  const double off[4] = {0, o1, o2, 0};
  t->setMatrix(v);
  t->setOffset(off);
  return t;
}

struct HueStage {
  double lo2, hi2, lo3, hi3;  // input ranges of channels 2 and 3
};

// The four LUT stages' input ranges; `ulo`, `uhi`: U at the ends of the log range.
std::vector<HueStage> hue_stages(double ulo, double uhi) {
  const double lo = kHueLogLo, hi = kHueLogHi;
  return {{lo, hi, lo, hi}, {lo, hi, lo, hi}, {ulo, uhi, lo + ulo, hi + uhi}, {lo, hi, lo + ulo - kHueKappa * hi, hi + uhi - kHueKappa * lo}};
}

// Decodes values stored as log2(y + 2^k).
OCIO::TransformRcPtr output_decode(int k) {
  auto t = OCIO::LogAffineTransform::Create();
  t->setBase(2.0);
  const double off[3] = {std::ldexp(1.0, k), std::ldexp(1.0, k), std::ldexp(1.0, k)};
  t->setLinSideOffsetValue(off);
  t->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return t;
}

OCIO::TransformRcPtr matrix(const color::Mat3& m) {
  auto t = OCIO::MatrixTransform::Create();
  double v[16] = {m.m[0][0], m.m[0][1], m.m[0][2], 0, m.m[1][0], m.m[1][1], m.m[1][2], 0,
                  m.m[2][0], m.m[2][1], m.m[2][2], 0, 0,         0,         0,         1};
  t->setMatrix(v);
  return t;
}

OCIO::TransformRcPtr clamp01() { return range_clamp(0.0, 1.0); }

OCIO::TransformRcPtr lut_transform(const BakedLut& lut, const std::string& file) {
  const Representation& r = lut.rep;
  if (!file.empty()) {
    auto f = OCIO::FileTransform::Create();
    f->setSrc(file.c_str());
    f->setInterpolation(r.dims == 1 ? OCIO::INTERP_LINEAR : OCIO::INTERP_TETRAHEDRAL);
    return f;
  }
  if (r.dims == 1) {
    auto t = OCIO::Lut1DTransform::Create();
    t->setLength(unsigned(r.size));
    for (int i = 0; i < r.size; ++i) {
      const float* v = r.luminance ? &lut.values[std::size_t(i) * 3] : &lut.values[i];
      t->setValue(unsigned(i), v[0], v[r.luminance ? 1 : 0], v[r.luminance ? 2 : 0]);
    }
    t->setInterpolation(OCIO::INTERP_LINEAR);
    return t;
  }
  auto t = OCIO::Lut3DTransform::Create();
  t->setGridSize(unsigned(r.size));
  const unsigned n = unsigned(r.size);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k) {
        const float* v = &lut.values[((std::size_t(i) * n + j) * n + k) * 3];
        t->setValue(i, j, k, v[0], v[1], v[2]);
      }
  t->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
  return t;
}

// After the LUT: decode, output matrix, clamp.
void append_tail(OCIO::GroupTransformRcPtr& g, const BakedLut& lut) {
  if (lut.rep.dims == 3) g->appendTransform(output_decode(lut.rep.out_log2));
  if (lut.output_matrix) g->appendTransform(matrix(*lut.output_matrix));
  g->appendTransform(clamp01());
}

}  // namespace

namespace {

// The node warp's density: at least kWarpFloor of its mean everywhere, smoothed by three box
// passes of +-kWarpSmooth of the entries. Measured on reinhard-jodie, 49^3 behind log2 [-8, 16]:
// max 0.83 code value; 0.90 and 0.87 with smoothing 0.05 and 0.1 (measured with an analytic sRGB
// slope); at 57^3 unsmoothed 2.9, uniform nodes 1.7.
constexpr double kWarpFloor = 0.05, kWarpSmooth = 0.08;

// The value a 3D LUT stores for display-linear y, and its inverse.
double encode_out(const Representation& r, double y) { return repro::log2(std::max(y, 0.0) + std::ldexp(1.0, r.out_log2)); }
double decode_out(const Representation& r, double v) { return repro::exp2(v) - std::ldexp(1.0, r.out_log2); }

// 10-bit sRGB code values per unit of stored value at v: how much an interpolation error there
// shows. Above 1 the clamp hides it, fading out by 1.25 (a value just above 1 can still be
// interpolated below it).
double code_values_per_unit(const Representation& r, double v) {
  const double dv = 1e-4 * std::max(1.0, std::abs(v));
  const double y = decode_out(r, v), slope = (decode_out(r, v + dv) - decode_out(r, v - dv)) / (2 * dv);
  const double yc = std::min(std::max(y, 0.0), 1.0), dy = 1e-6 * std::max(yc, 1e-3);
  const double srgb_slope = (srgb_encode(yc + dy) - srgb_encode(std::max(yc - dy, 0.0))) / (yc + dy - std::max(yc - dy, 0.0));
  const double fade = y <= 1.0 ? 1.0 : std::max(0.0, 1.0 - (y - 1.0) / 0.25);
  return 1023.0 * srgb_slope * std::abs(slope) * fade;
}

}  // namespace

std::vector<float> node_warp(const operators::Evaluator& ev, const Representation& rep) {
  const int m = rep.warp_size;
  std::vector<double> levels{0.0};
  for (int k = 0; k <= 10; ++k) levels.push_back(rep.shaper.inverse(k / 10.0));
  std::vector<double> axis(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) axis[i] = rep.shaper.inverse(double(i) / (m - 1));
  std::vector<float> warp(std::size_t(m) * 3);
  for (int c = 0; c < 3; ++c) {
    // need[i]: the largest |f''| x sensitivity at entry i over every line and output channel.
    std::vector<double> need(static_cast<std::size_t>(m), 0.0);
    std::vector<float> line(std::size_t(m) * 3);
    for (double p : levels)
      for (double q : levels) {
        for (int i = 0; i < m; ++i) {
          float* px = &line[std::size_t(i) * 3];
          px[c] = float(axis[i]);
          px[(c + 1) % 3] = float(p);
          px[(c + 2) % 3] = float(q);
        }
        ev.apply(line.data(), std::size_t(m), 3);
        for (int o = 0; o < 3; ++o)
          for (int i = 1; i + 1 < m; ++i) {
            const double v0 = encode_out(rep, line[std::size_t(i - 1) * 3 + o]), v1 = encode_out(rep, line[std::size_t(i) * 3 + o]),
                         v2 = encode_out(rep, line[std::size_t(i + 1) * 3 + o]);
            const double d2 = std::abs(v0 - 2 * v1 + v2) * double(m - 1) * double(m - 1);
            if (std::isfinite(d2)) need[i] = std::max(need[i], d2 * code_values_per_unit(rep, v1));
          }
      }
    // Node density per interval: sqrt of the need, the largest within a few entries (a node
    // interval spans many entries), with a floor so that no region is left without nodes, then
    // smoothed: a density that changes fast bends the node coordinate, which costs as much as
    // the curvature it removes.
    std::vector<double> density(static_cast<std::size_t>(m - 1));
    double mean = 0;
    const int reach = std::max(1, m / 128);
    for (int i = 0; i + 1 < m; ++i) {
      double d = 0;
      for (int k = std::max(0, i - reach); k <= std::min(m - 1, i + 1 + reach); ++k) d = std::max(d, need[k]);
      density[i] = std::sqrt(d);
      mean += density[i] / (m - 1);
    }
    for (double& d : density) d = std::max(d, kWarpFloor * mean + 1e-12);
    const int width = std::max(1, int(kWarpSmooth * m));
    for (int pass = 0; pass < 3; ++pass) {
      std::vector<double> sm(density.size());
      for (int i = 0; i + 1 < m; ++i) {
        double sum = 0;
        int cnt = 0;
        for (int k = std::max(0, i - width); k <= std::min(m - 2, i + width); ++k, ++cnt) sum += density[k];
        sm[i] = sum / cnt;
      }
      density = sm;
    }
    double total = 0;
    for (double d : density) total += d;
    double acc = 0;
    warp[c] = 0.f;
    for (int i = 0; i + 1 < m; ++i) {
      acc += density[i];
      warp[std::size_t(i + 1) * 3 + c] = float(acc / total);
    }
    warp[std::size_t(m - 1) * 3 + c] = 1.f;
  }
  return warp;
}

bool hue_steps_apply(const operators::Evaluator& ev) {
  const auto* st = ev.hue_keeping_steps();
  if (!st || ev.input_matrix || ev.output_matrix) return false;
  double prev = -INFINITY;
  for (int i = 0; i <= 4096; ++i) {
    const double u = hue_u(*st, kHueLogLo + (kHueLogHi - kHueLogLo) * i / 4096.0);
    if (!(u > prev)) return false;
    prev = u;
  }
  return true;
}

color::Mat3 rgb_to_ryb() {
  return color::Mat3{{{{1, 0, 0}, {color::kLumR, color::kLumG, color::kLumB}, {0, 0, 1}}}};
}

bool scales_by_luminance(const operators::Evaluator& ev) {
  if (ev.input_matrix || ev.output_matrix) return false;
  const double levels[] = {0, 1e-4, 0.02, 0.18, 0.7, 3, 50, 2000, 65504};
  std::vector<float> in;
  for (double r : levels)
    for (double g : levels)
      for (double b : levels)
        if (r + g + b > 0) in.insert(in.end(), {float(r), float(g), float(b)});
  std::vector<float> out = in;
  ev.apply(out.data(), out.size() / 3, 3);
  try {
    for (std::size_t i = 0; i < in.size(); i += 3) {
      const double y = color::luminance(double(in[i]), double(in[i + 1]), double(in[i + 2]));
      const double k = ev.curve(y) / y;
      for (int c = 0; c < 3; ++c) {
        const double want = in[i + c] * k;
        if (!(std::abs(out[i + c] - want) <= 1e-3 * std::abs(want) + 1e-12)) return false;
      }
    }
  } catch (const std::exception&) {
    return false;  // no scalar curve
  }
  return true;
}

std::vector<double> node_axis(const Representation& rep, const std::vector<float>& warp, int c) {
  const int n = rep.size;
  std::vector<double> axis(static_cast<std::size_t>(n));
  int e = 0;
  for (int i = 0; i < n; ++i) {
    double u = double(i) / (n - 1);
    if (rep.warped) {
      const int m = rep.warp_size;
      const double t = u;
      while (e + 2 < m && double(warp[std::size_t(e + 1) * 3 + c]) < t) ++e;
      const double s0 = warp[std::size_t(e) * 3 + c], s1 = warp[std::size_t(e + 1) * 3 + c];
      u = (e + std::clamp((t - s0) / (s1 - s0), 0.0, 1.0)) / (m - 1);
    }
    axis[std::size_t(i)] = rep.shaper.inverse(u);
  }
  return axis;
}

double warp_at(const Representation& rep, const std::vector<float>& warp, int c, double u) {
  if (!rep.warped) return u;
  const double f = std::clamp(u, 0.0, 1.0) * (rep.warp_size - 1);
  const int e = std::min(int(f), rep.warp_size - 2);
  const double w0 = warp[std::size_t(e) * 3 + c], w1 = warp[std::size_t(e + 1) * 3 + c];
  return w0 + (f - e) * (w1 - w0);
}

BakedLut sample_lut(const operators::Evaluator& ev, const Representation& rep) {
  BakedLut out;
  out.rep = rep;
  out.input_matrix = ev.input_matrix;
  out.output_matrix = ev.output_matrix;
  const int n = rep.size;
  if (rep.dims == 1 && rep.hue_steps) {
    // Four tables of n entries, each the channel-2 column of its stage (hue_stages).
    const auto& st = *ev.hue_keeping_steps();
    out.values.resize(std::size_t(n) * 4);
    float* toe = &out.values[0];
    float* u = &out.values[std::size_t(n)];
    float* u_inv = &out.values[std::size_t(n) * 2];
    float* shoulder = &out.values[std::size_t(n) * 3];
    auto at = [&](int i) { return kHueLogLo + (kHueLogHi - kHueLogLo) * i / (n - 1); };
    auto linear = [](double x) { return std::max(repro::exp2(x) - kHueEps, 0.0); };
    for (int i = 0; i < n; ++i) {
      toe[i] = float(repro::log2(std::max(st.toe(linear(at(i))), 0.0) + kHueEps));
      u[i] = float(hue_u(st, at(i)));
      shoulder[i] = float(repro::log2(st.shoulder(linear(at(i))) + kHueEps));
    }
    const double ulo = u[0], uhi = u[n - 1];
    for (int i = 0; i < n; ++i) {
      const double target = ulo + (uhi - ulo) * i / (n - 1);
      double a = kHueLogLo, b = kHueLogHi;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (a + b);
        (hue_u(st, mid) < target ? a : b) = mid;
      }
      u_inv[i] = float(0.5 * (a + b));
    }
    return out;
  }
  if (rep.dims == 1 && rep.luminance) {
    // (x, y, Y) -> (x, y, curve(Y)): the LUT's input is [0, 1] on every channel, the shaper
    // applies to Y only, so x and y take the identity.
    out.values.resize(std::size_t(n) * 3);
    for (int i = 0; i < n; ++i) {
      const double u = double(i) / (n - 1);
      out.values[std::size_t(i) * 3] = out.values[std::size_t(i) * 3 + 1] = float(u);
      out.values[std::size_t(i) * 3 + 2] = float(ev.curve(rep.shaper.inverse(u)));
    }
    return out;
  }
  if (rep.dims == 1) {
    out.values.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) out.values[i] = float(ev.curve(rep.shaper.inverse(double(i) / (n - 1))));
    return out;
  }
  // 3D: the whole operator (matrices included) on every node, unclamped.
  // Warped: node j of channel c sits where the pre-curve (linear between its entries, as OCIO
  // interpolates it) reaches j / (n - 1); otherwise at shaper value j / (n - 1).
  std::vector<double> axes[3];
  if (rep.warped) out.warp = node_warp(ev, rep);
  for (int c = 0; c < 3; ++c) axes[c] = node_axis(rep, out.warp, c);
  const std::size_t nodes = std::size_t(n) * n * n;
  out.values.resize(nodes * 3);
  out.input_matrix.reset();
  out.output_matrix.reset();
  parallel_rows(n, [&](int64_t i0, int64_t i1) {
    for (int64_t i = i0; i < i1; ++i) {
      float* row = &out.values[std::size_t(i) * n * n * 3];
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          float* p = row + (std::size_t(j) * n + k) * 3;
          p[0] = float(axes[0][i]);
          p[1] = float(axes[1][j]);
          p[2] = float(axes[2][k]);
        }
      ev.apply(row, std::size_t(n) * n, 3);
      for (std::size_t q = 0; q < std::size_t(n) * n * 3; ++q) row[q] = float(encode_out(rep, row[q]));
    }
  });
  return out;
}

OCIO::GroupTransformRcPtr view_transform(const BakedLut& lut, const std::string& lut_file) {
  auto g = OCIO::GroupTransform::Create();
  if ((lut.rep.hue_steps || lut.rep.warped) && !lut_file.empty()) {
    auto f = OCIO::FileTransform::Create();
    f->setSrc(lut_file.c_str());
    f->setInterpolation(OCIO::INTERP_LINEAR);
    g->appendTransform(f);
    return g;
  }
  if (lut.rep.hue_steps) {
    const int n = lut.rep.size;
    const float* table = lut.values.data();
    const auto stages = hue_stages(table[n], table[2 * n - 1]);
    // One LUT stage: channel 2 through table `k`, channels 1 and 3 identity.
    auto stage = [&](int k) {
      const HueStage& r = stages[std::size_t(k)];
      g->appendTransform(hue_matrix(1 / (r.hi2 - r.lo2), 0, 0, 1 / (r.hi3 - r.lo3), -r.lo2 / (r.hi2 - r.lo2), -r.lo3 / (r.hi3 - r.lo3)));
      auto t = OCIO::Lut1DTransform::Create();
      t->setLength(unsigned(n));
      for (int i = 0; i < n; ++i) {
        const double u = double(i) / (n - 1);
        t->setValue(unsigned(i), float(u), table[std::size_t(k) * n + i], float(r.lo3 + u * (r.hi3 - r.lo3)));
      }
      t->setInterpolation(OCIO::INTERP_LINEAR);
      g->appendTransform(t);
    };
    g->appendTransform(clamp_input());
    g->appendTransform(OCIO::FixedFunctionTransform::Create(OCIO::FIXED_FUNCTION_RGB_TO_HSV));
    g->appendTransform(hue_matrix(-1, 0, 0, 1, 1, 0));            // (H, 1 - S, V)
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_FORWARD));    // (H, log2(1 - S), log2 V)
    g->appendTransform(hue_matrix(1, 1, 0, 1));                   // (H, log2 m, log2 V)
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_INVERSE));    // (H, m, V)
    g->appendTransform(hue_matrix(1, 0, -1, 1));                  // (H, m, delta)
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_FORWARD));
    stage(0);                                                     // (H, log2 toe(m), log2 delta)
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_INVERSE));
    g->appendTransform(hue_matrix(1, 1, 0, 1));                   // (H, V', delta)
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_FORWARD));    // (H, a, b)
    stage(1);                                                     // (H, U, b)
    g->appendTransform(hue_matrix(1, 0, 1, 1));                   // (H, U, b + U)
    stage(2);                                                     // (H, a, b + U)
    g->appendTransform(hue_matrix(1, 0, -kHueKappa, 1));          // (H, a, b + log2 R)
    stage(3);                                                     // (H, log2 shoulder, b + log2 R)
    g->appendTransform(hue_matrix(1, 0, -1, 1));                  // (H, log2 shoulder, log2 S'')
    g->appendTransform(hue_logs(OCIO::TRANSFORM_DIR_INVERSE, 0.0));
    g->appendTransform(hue_matrix(0, 1, 1, 0));                   // (H, S'', V'')
    auto to_rgb = OCIO::FixedFunctionTransform::Create(OCIO::FIXED_FUNCTION_RGB_TO_HSV);
    to_rgb->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
    g->appendTransform(to_rgb);
    g->appendTransform(clamp01());
    return g;
  }
  if (lut.rep.warped) {
    // Inputs clamped to [0, 65504] as cgtmo apply sanitises them; the pre-curve behind the shaper.
    g->appendTransform(clamp_input());
    g->appendTransform(lut.rep.shaper.transform());
    auto pre = OCIO::Lut1DTransform::Create();
    pre->setLength(unsigned(lut.rep.warp_size));
    for (int i = 0; i < lut.rep.warp_size; ++i) {
      const float* w = &lut.warp[std::size_t(i) * 3];
      pre->setValue(unsigned(i), w[0], w[1], w[2]);
    }
    pre->setInterpolation(OCIO::INTERP_LINEAR);
    g->appendTransform(pre);
    g->appendTransform(lut_transform(lut, ""));
    append_tail(g, lut);
    return g;
  }
  if (lut.rep.luminance) {
    g->appendTransform(clamp_input());
    g->appendTransform(matrix(rgb_to_ryb()));
    g->appendTransform(xyy(OCIO::TRANSFORM_DIR_FORWARD));
    g->appendTransform(luminance_shaper(lut.rep.shaper));
    g->appendTransform(lut_transform(lut, lut_file));
    g->appendTransform(xyy(OCIO::TRANSFORM_DIR_INVERSE));
    g->appendTransform(matrix(rgb_to_ryb().inverse()));
    g->appendTransform(clamp01());
    return g;
  }
  if (lut.input_matrix) {
    // Clamped first, as cgtmo apply sanitises: the matrix would carry a negative component (a
    // colour outside Rec.709) into the other channels, where the shaper no longer clips it.
    g->appendTransform(clamp_input());
    g->appendTransform(matrix(*lut.input_matrix));
  }
  g->appendTransform(lut.rep.shaper.transform());
  g->appendTransform(lut_transform(lut, lut_file));
  append_tail(g, lut);
  return g;
}

OCIO::GroupTransformRcPtr look_transform(const BakedLut& lut, const std::string& lut_file) {
  auto g = OCIO::GroupTransform::Create();
  g->appendTransform(kShaperSpace.transform(OCIO::TRANSFORM_DIR_INVERSE));
  auto v = view_transform(lut, lut_file);
  for (int i = 0; i < v->getNumTransforms(); ++i) g->appendTransform(v->getTransform(i));
  g->appendTransform(kShaperSpace.transform());
  return g;
}

}  // namespace cgtmo::bake
