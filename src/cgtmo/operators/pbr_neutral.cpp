// Khronos PBR Neutral: keeps base colours unchanged up to 0.76, then compresses the peak channel
// and desaturates toward white in proportion to the compression.
#include <algorithm>

#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

class PbrNeutralEvaluator final : public Evaluator {
 public:
  PbrNeutralEvaluator() : Evaluator(Kind::Mixing) {}
  void apply(float* px, std::size_t count, std::size_t stride) const override {
    constexpr float start = 0.8f - 0.04f;
    constexpr float desaturation = 0.15f;
    constexpr float d = 1.f - start;
    for (std::size_t i = 0; i < count; ++i, px += stride) {
      float c[3] = {std::max(px[0], 0.f), std::max(px[1], 0.f), std::max(px[2], 0.f)};
      const float x = std::min({c[0], c[1], c[2]});
      const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
      for (float& v : c) v -= offset;
      const float peak = std::max({c[0], c[1], c[2]});
      if (peak >= start) {
        const float new_peak = 1.f - d * d / (peak + d - start);
        const float s = new_peak / peak;
        const float g = 1.f - 1.f / (desaturation * (peak - new_peak) + 1.f);
        for (float& v : c) v = v * s + (new_peak - v * s) * g;
      }
      px[0] = clamp01(c[0]);
      px[1] = clamp01(c[1]);
      px[2] = clamp01(c[2]);
    }
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
