// The fast float path of every curve operator (curve_table.h: the table, the fused 8-pixel
// pipelines for strides 3 and 4, the plane pipeline for the rest) against the operator's exact
// double curve and matrices, composed here in double: out = clamp01(M_out * curve(max(M_in * in, 0))).
// ctest runs this binary once more per SIMD level (CGTMO_ISA=baseline, avx2, avx512).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "cgtmo/operators/curve_table.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::operators {
namespace {

struct Ref {
  const Evaluator* ev;
  // The exact composition in double; NaN in -> 0 out (clamp01's convention), as is +-Inf handled
  // by the curve's own limit.
  void operator()(const float* in, double* out) const {
    double c[3] = {in[0], in[1], in[2]};
    auto mul = [](const color::Mat3& m, double* v) {
      double r[3];
      for (int i = 0; i < 3; ++i) r[i] = m.m[i][0] * v[0] + m.m[i][1] * v[1] + m.m[i][2] * v[2];
      std::copy(r, r + 3, v);
    };
    if (ev->input_matrix) mul(*ev->input_matrix, c);
    for (double& v : c) v = ev->curve(std::max(v, 0.0));
    if (ev->output_matrix) mul(*ev->output_matrix, c);
    for (int k = 0; k < 3; ++k) out[k] = std::isnan(c[k]) ? 0.0 : std::clamp(c[k], 0.0, 1.0);
  }
};

// Random colours, log-uniform over [2^-30, 2^18] (so some lanes leave the table), with zeros,
// negatives and denormals mixed in, and the count not a multiple of 8 (the tails).
std::vector<float> random_pixels(std::size_t count, std::size_t stride, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> stops(-30.0, 18.0), u(0.0, 1.0);
  std::vector<float> px(count * stride);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < stride; ++k) {
      double v = std::exp2(stops(rng));
      const double pick = u(rng);
      if (pick < 0.02) v = 0.0;
      else if (pick < 0.04) v = -v;
      else if (pick < 0.05) v = 1e-40;  // denormal
      px[i * stride + k] = k == 3 ? float(u(rng)) : float(v);
    }
  return px;
}

ParamValues defaults_of(const OperatorDef& op) {
  ImageStats stats;
  stats.max_channel = 16.0;
  stats.max_luminance = 16.0;
  stats.log_average_luminance = 0.18;
  return resolve_params(op, {}, &stats);
}

// Largest error of the fast path against the double composition, after clamping.
double max_error(const Evaluator& ev, std::vector<float> px, std::size_t stride) {
  const std::vector<float> in = px;
  ev.apply(px.data(), px.size() / stride, stride);
  const Ref ref{&ev};
  double worst = 0.0;
  for (std::size_t i = 0; i < px.size(); i += stride) {
    double want[3];
    ref(&in[i], want);
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(double(px[i + k]) - want[k]));
    if (stride == 4) {
      EXPECT_EQ(px[i + 3], in[i + 3]) << "alpha changed at pixel " << i / stride;
    }
  }
  return worst;
}

TEST(CurveTable, PerChannelOperatorsMatchTheExactCurveForEveryStride) {
  int tested = 0;
  for (const OperatorDef& op : operators_of(Scope::Pixel)) {
    auto ev = op.make(defaults_of(op));
    if (ev->kind() != Kind::PerChannel) continue;
    ++tested;
    for (std::size_t stride : {3u, 4u, 5u}) {
      const double err = max_error(*ev, random_pixels(4099, stride, 7u + unsigned(stride)), stride);
      // The table's interpolation error is below 3e-5 linear for every curve (docs/performance.md);
      // 1e-4 still catches a wrong lane, channel or matrix by orders of magnitude.
      EXPECT_LT(err, 1e-4) << op.name << " stride " << stride << " (kernels: " << CurveTable::isa() << ")";
    }
  }
  EXPECT_GE(tested, 8);
}

TEST(CurveTable, NonFiniteLanesTakeTheExactPathAndLeaveTheirNeighboursAlone) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const char* name : {"aces-hill", "agx", "lottes", "hable"}) {
    const OperatorDef& op = find_operator(name);
    auto ev = op.make(defaults_of(op));
    for (std::size_t stride : {3u, 4u}) {
      // 40 pixels: two or more fused groups (8 or 16 pixels, by the CPU); one bad value in the first.
      constexpr std::size_t kPixels = 40;
      std::vector<float> px(kPixels * stride, 0.5f);
      const std::vector<float> clean = [&] {
        std::vector<float> c = px;
        ev->apply(c.data(), kPixels, stride);
        return c;
      }();
      for (float bad : {nan, inf, -inf, 1e30f, 65504.f * 2.f}) {
        std::vector<float> v = px;
        v[5 * stride + 1] = bad;
        ev->apply(v.data(), kPixels, stride);
        for (std::size_t i = 0; i < v.size(); ++i) {
          ASSERT_TRUE(std::isfinite(v[i])) << name << " bad " << bad << " index " << i;
          ASSERT_GE(v[i], 0.f);
          ASSERT_LE(v[i], 1.f);
          // The bad value's group of 8 or 16 pixels is redone by the plane pipeline, whose
          // rounding (FMA contraction of the matrices) may differ in the last bit.
          if (i / stride == 5) continue;
          if (i / stride < 16) EXPECT_NEAR(v[i], clean[i], 1e-6) << name << " bad " << bad << " index " << i;
          else EXPECT_EQ(v[i], clean[i]) << name << " bad " << bad << " index " << i;
        }
        double want[3];
        const float in[3] = {0.5f, bad, 0.5f};
        Ref{ev.get()}(in, want);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[5 * stride + k], want[k], 1e-4) << name << " bad " << bad;
      }
    }
  }
}

}  // namespace
}  // namespace cgtmo::operators
