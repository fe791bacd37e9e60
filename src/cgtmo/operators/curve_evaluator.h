#pragma once
// The shared evaluation of every operator built on a scalar curve: per channel, on luminance or
// on max(R,G,B), optionally between two matrices. Each curve is written once, as a functor with
// `template <class T> T operator()(T x) const`, and this template inlines it into the pixel loop.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "cgtmo/color/luminance.h"
#include "cgtmo/operators/operator.h"

namespace cgtmo::operators {

// NaN-safe clamp to [0, 1]: NaN goes to 0.
inline float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

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

  void apply(float* px, std::size_t count, std::size_t stride) const override {
    switch (mode_) {
      case Mode::PerChannel: run(px, count, stride, [this](float& r, float& g, float& b) {
          r = curve_(std::max(r, 0.f));
          g = curve_(std::max(g, 0.f));
          b = curve_(std::max(b, 0.f));
        });
        break;
      case Mode::Luminance: run(px, count, stride, [this](float& r, float& g, float& b) {
          const float l = std::max(color::luminance(r, g, b), 0.f);
          scale_by(r, g, b, l, curve_(l));
        });
        break;
      case Mode::MaxRGB: run(px, count, stride, [this](float& r, float& g, float& b) {
          const float m = std::max({r, g, b, 0.f});
          scale_by(r, g, b, m, curve_(m));
        });
        break;
    }
  }

 private:
  template <class F>
  void run(float* px, std::size_t count, std::size_t stride, F&& f) const {
    for (std::size_t i = 0; i < count; ++i, px += stride) {
      float r = px[0], g = px[1], b = px[2];
      if (input_matrix) input_matrix->apply(r, g, b);
      f(r, g, b);
      if (output_matrix) output_matrix->apply(r, g, b);
      px[0] = clamp01(r);
      px[1] = clamp01(g);
      px[2] = clamp01(b);
    }
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
      r = float(out * std::pow(std::max(r, 0.f) * inv, double(saturation_)));
      g = float(out * std::pow(std::max(g, 0.f) * inv, double(saturation_)));
      b = float(out * std::pow(std::max(b, 0.f) * inv, double(saturation_)));
    }
  }

  Curve curve_;
  Mode mode_;
  float saturation_;
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
