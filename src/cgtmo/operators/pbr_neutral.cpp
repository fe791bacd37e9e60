// Khronos PBR Neutral: keeps base colours unchanged up to 0.76, then compresses the peak channel
// and desaturates toward white in proportion to the compression.
#include <algorithm>

#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

class PbrNeutralEvaluator final : public Evaluator {
 public:
  PbrNeutralEvaluator() : Evaluator(Kind::Mixing) {}
  // Over planes so that the loop vectorises (apply_in_planes): the compression is computed for
  // every pixel and kept where peak >= start, the same arithmetic as the branch it replaces;
  // min and max keep std::min/max({...})'s order, so NaN is treated as before.
  void apply(float* px, std::size_t count, std::size_t stride) const override {
    apply_in_planes(px, count, stride, clamp_output, [](float* r, float* g, float* b, std::size_t n) {
      constexpr float start = 0.8f - 0.04f;
      constexpr float desaturation = 0.15f;
      constexpr float d = 1.f - start;
      for (std::size_t j = 0; j < n; ++j) {
        float c0 = std::max(r[j], 0.f), c1 = std::max(g[j], 0.f), c2 = std::max(b[j], 0.f);
        float x = c0;
        x = c1 < x ? c1 : x;
        x = c2 < x ? c2 : x;
        const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
        c0 -= offset;
        c1 -= offset;
        c2 -= offset;
        float peak = c0;
        peak = peak < c1 ? c1 : peak;
        peak = peak < c2 ? c2 : peak;
        const float new_peak = 1.f - d * d / (peak + d - start);
        const float s = new_peak / peak;
        const float gd = 1.f - 1.f / (desaturation * (peak - new_peak) + 1.f);
        const bool compress = peak >= start;
        r[j] = compress ? c0 * s + (new_peak - c0 * s) * gd : c0;
        g[j] = compress ? c1 * s + (new_peak - c1 * s) * gd : c1;
        b[j] = compress ? c2 * s + (new_peak - c2 * s) * gd : c2;
      }
    });
  }
};

}  // namespace

OperatorDef pbr_neutral_operator() {
  OperatorDef d;
  d.name = "pbr-neutral";
  d.summary = "Khronos PBR Neutral: colour-faithful below 0.76, peak compression and desaturation above";
  d.citation = "Khronos Group, PBR Neutral Tone Mapping specification, 2024";
  d.default_kind = Kind::Mixing;
  d.make = [](const ParamValues&) -> std::unique_ptr<Evaluator> { return std::make_unique<PbrNeutralEvaluator>(); };
  return d;
}

}  // namespace cgtmo::operators
