#pragma once
// The shared evaluation of every operator built on a scalar curve: per channel, on luminance or
// on max(R,G,B), optionally between two matrices. Each curve is written once, as a functor with
// `template <class T> T operator()(T x) const`; apply() evaluates it through a table of the exact
// double curve (curve_table.h), and curve() exactly, for the LUT baker.
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

#include "cgtmo/color/luminance.h"
#include "cgtmo/operators/curve_table.h"
#include "cgtmo/operators/operator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {

// NaN-safe clamp to [0, 1]: NaN goes to 0.
inline float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

// Runs f(r, g, b, n) over blocks of at most 256 pixels split into planes, so that the loop inside
// f vectorises, then writes RGB back, clamped to [0, 1] when `clamp` (alpha is left alone).
// For evaluators that are not a scalar curve (their source file is compiled with
// -fno-trapping-math, see src/cgtmo/CMakeLists.txt, so that branch-free selects around divisions
// vectorise).
template <class F>
void apply_in_planes(float* px, std::size_t count, std::size_t stride, bool clamp, F&& f) {
  constexpr std::size_t kBlock = 256;
  alignas(32) float r[kBlock], g[kBlock], b[kBlock];
  for (std::size_t i0 = 0; i0 < count; i0 += kBlock) {
    const std::size_t n = std::min(kBlock, count - i0);
    float* p = px + i0 * stride;
    planes_from_pixels(p, n, stride, r, g, b);
    f(r, g, b, n);
    pixels_from_planes(r, g, b, n, clamp, p, stride);
  }
}

struct CurveOptions {
  Mode mode = Mode::PerChannel;
  double saturation = 1.0;  // luminance mode: out = Lout * (C / Lin)^saturation
  std::optional<color::Mat3> input_matrix;
  std::optional<color::Mat3> output_matrix;
};

template <class Curve>
class CurveEvaluator final : public Evaluator {
 public:
  CurveEvaluator(Curve curve, CurveOptions opt)
      : Evaluator(opt.mode == Mode::PerChannel ? Kind::PerChannel : Kind::Mixing),
        curve_(std::move(curve)),
        mode_(opt.mode),
        saturation_(float(opt.saturation)) {
    input_matrix = opt.input_matrix;
    output_matrix = opt.output_matrix;
  }

  double curve(double x) const override { return curve_(std::max(x, 0.0)); }

  // Through the curve's table (curve_table.h), built on first use from the exact double curve;
  // the pipeline runs over planes, vectorised. Inputs the table does not cover (>= 2^16, NaN)
  // take the exact float curve.
  void apply(float* px, std::size_t count, std::size_t stride) const override {
    float in_m[9], out_m[9];
    CurveApply a;
    a.table = &table();
    a.mode = mode_ == Mode::PerChannel ? CurveApply::Mode::PerChannel
             : mode_ == Mode::Luminance ? CurveApply::Mode::Luminance
                                        : CurveApply::Mode::MaxRGB;
    a.saturation_is_one = saturation_ == 1.f;
    if (input_matrix) a.input_matrix = to_float(*input_matrix, in_m);
    if (output_matrix) a.output_matrix = to_float(*output_matrix, out_m);
    a.clamp = clamp_output;
    a.context = this;
    // In double: a float curve overflows in x * x for huge finite x (1e30 came out black).
    a.exact_curve = [](const void* self, float x) {
      return float(static_cast<const CurveEvaluator*>(self)->curve_(double(x)));
    };
    a.exact_scale = [](const void* self, float& r, float& g, float& b, float in, float out) {
      static_cast<const CurveEvaluator*>(self)->scale_by(r, g, b, in, out);
    };
    apply_curve(a, px, count, stride);
  }

 private:
  const CurveTable& table() const {
    std::call_once(table_once_, [this] { table_ = std::make_unique<CurveTable>([this](double x) { return curve_(x); }); });
    return *table_;
  }

  static const float* to_float(const color::Mat3& m, float* out) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out[i * 3 + j] = float(m.m[i][j]);
    return out;
  }

  // Scales RGB so that `in` (luminance or max) becomes `out`; the ratio in double because `in`
  // may be denormal. Black stays black.
  void scale_by(float& r, float& g, float& b, float in, float out) const {
    if (!(in > 0.f)) {
      r = g = b = 0.f;
      return;
    }
    if (saturation_ == 1.f) {
      const double s = double(out) / double(in);
      r = float(std::max(r, 0.f) * s);
      g = float(std::max(g, 0.f) * s);
      b = float(std::max(b, 0.f) * s);
    } else {
      const double inv = 1.0 / double(in);
      r = float(out * repro::pow(std::max(r, 0.f) * inv, double(saturation_)));
      g = float(out * repro::pow(std::max(g, 0.f) * inv, double(saturation_)));
      b = float(out * repro::pow(std::max(b, 0.f) * inv, double(saturation_)));
    }
  }

  Curve curve_;
  Mode mode_;
  float saturation_;
  mutable std::once_flag table_once_;
  mutable std::unique_ptr<CurveTable> table_;
};

template <class Curve>
std::unique_ptr<Evaluator> make_curve_evaluator(Curve c, CurveOptions opt = {}) {
  return std::make_unique<CurveEvaluator<Curve>>(std::move(c), std::move(opt));
}

// The `mode` and `saturation` parameters shared by operators whose source leaves the choice open.
ParamSpec mode_param(Mode default_mode);
ParamSpec saturation_param();
// Reads them back (both present when mode_param was listed).
CurveOptions curve_options_from(const ParamValues& v);

}  // namespace cgtmo::operators
