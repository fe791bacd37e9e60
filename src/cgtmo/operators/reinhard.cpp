// The Reinhard family (Reinhard et al. 2002, "Photographic tone reproduction for digital images",
// Eq. 3 and 4) and Jodie's per-channel/luminance blend.
#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

constexpr double kMaxValue = 65504.0;  // the half-float maximum: the top of every input domain

struct ReinhardCurve {
  template <class T>
  T operator()(T x) const {
    return x / (T(1) + x);
  }
};

// L (1 + L / Lwhite^2) / (1 + L): maps `white` to exactly 1.
struct ReinhardExtendedCurve {
  double inv_white_sq;
  template <class T>
  T operator()(T x) const {
    return x * (T(1) + x * T(inv_white_sq)) / (T(1) + x);
  }
};

ReinhardExtendedCurve extended(double white) { return {1.0 / (white * white)}; }

// Jodie's blend: lerp(C / (1 + L), C / (1 + C), C / (1 + C)) per channel.
class ReinhardJodieEvaluator final : public Evaluator {
 public:
  ReinhardJodieEvaluator() : Evaluator(Kind::Mixing) {}
  // Over planes so that the loop vectorises (apply_in_planes); the same arithmetic per pixel.
  void apply(float* px, std::size_t count, std::size_t stride) const override {
    apply_in_planes(px, count, stride, clamp_output, [](float* r, float* g, float* b, std::size_t n) {
      for (std::size_t j = 0; j < n; ++j) {
        const float cr = std::max(r[j], 0.f), cg = std::max(g[j], 0.f), cb = std::max(b[j], 0.f);
        const float inv = 1.f / (1.f + color::luminance(cr, cg, cb));
        r[j] = blend(cr, inv);
        g[j] = blend(cg, inv);
        b[j] = blend(cb, inv);
      }
    });
  }

 private:
  static float blend(float c, float inv_one_plus_l) {
    const float tv = c / (1.f + c);
    const float lv = c * inv_one_plus_l;
    return lv + (tv - lv) * tv;
  }
};

}  // namespace

OperatorDef reinhard_operator() {
  OperatorDef d;
  d.name = "reinhard";
  d.summary = "x / (1 + x)";
  d.citation = "Reinhard, Stark, Shirley, Ferwerda, Photographic Tone Reproduction for Digital Images, SIGGRAPH 2002, Eq. 3";
  d.default_kind = Kind::PerChannel;
  d.params = {mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) { return make_curve_evaluator(ReinhardCurve{}, curve_options_from(v)); };
  return d;
}

OperatorDef reinhard_ext_operator() {
  OperatorDef d;
  d.name = "reinhard-ext";
  d.summary = "extended Reinhard per channel: x (1 + x / white^2) / (1 + x)";
  d.citation = "Reinhard et al., SIGGRAPH 2002, Eq. 4, applied per channel";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("white", 1.0, 1e-6, kMaxValue, "input value mapped to 1 (default: the image's largest channel value)",
                           ImageDefault::MaxChannel),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    return make_curve_evaluator(extended(v.number("white")), curve_options_from(v));
  };
  return d;
}

OperatorDef reinhard_lum_operator() {
  OperatorDef d;
  d.name = "reinhard-lum";
  d.summary = "extended Reinhard on luminance, colour scaled by Lout / Lin";
  d.citation = "Reinhard et al., SIGGRAPH 2002, Eq. 4, on luminance as the paper defines it";
  d.default_kind = Kind::Mixing;
  d.params = {number_param("white", 1.0, 1e-6, kMaxValue, "luminance mapped to 1 (default: the image's largest luminance)",
                           ImageDefault::MaxLuminance),
              saturation_param()};
  d.make = [](const ParamValues& v) {
    CurveOptions o;
    o.mode = Mode::Luminance;
    o.saturation = v.number("saturation");
    return make_curve_evaluator(extended(v.number("white")), o);
  };
  return d;
}

OperatorDef reinhard_jodie_operator() {
  OperatorDef d;
  d.name = "reinhard-jodie";
  d.summary = "blend of per-channel and luminance Reinhard, weighted by the per-channel result";
  d.citation = "Jodie Reinhard's variant, as given in the seed tone-mapping guide (reinhard_jodie)";
  d.default_kind = Kind::Mixing;
  d.make = [](const ParamValues&) -> std::unique_ptr<Evaluator> { return std::make_unique<ReinhardJodieEvaluator>(); };
  return d;
}

}  // namespace cgtmo::operators
