// Khronos PBR Neutral: keeps base colours unchanged up to 0.76, then compresses the peak channel
// and desaturates toward white in proportion to the compression.
#include <algorithm>

#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

// The specification's constants and its three pieces, written once: apply() runs them in float,
// hue_keeping_steps() in double for the LUT baker.
constexpr float kStart = 0.8f - 0.04f;
constexpr float kDesaturation = 0.15f;
constexpr float kD = 1.f - kStart;

// The offset subtracted from every channel, from the smallest channel x.
template <class T>
T offset_of(T x) {
  return x < T(0.08f) ? x - T(6.25f) * x * x : T(0.04f);
}
// The compressed peak (used where peak >= kStart).
template <class T>
T new_peak_of(T peak) {
  return T(1) - T(kD) * T(kD) / (peak + T(kD) - T(kStart));
}
// The share of the way to the new peak (grey) that every channel moves.
template <class T>
T desaturation_of(T peak, T new_peak) {
  return T(1) - T(1) / (T(kDesaturation) * (peak - new_peak) + T(1));
}

class PbrNeutralEvaluator final : public Evaluator {
 public:
  PbrNeutralEvaluator() : Evaluator(Kind::Mixing) {
    // c - offset keeps the channel order: the minimum m becomes m - offset(m). Then
    // out = c s + (new_peak - c s) gd with s = new_peak / peak: the maximum becomes new_peak and
    // (max - min) / max is multiplied by 1 - gd.
    steps_.toe = [](double m) { return m - offset_of(m); };
    steps_.shoulder = [](double p) { return p >= double(kStart) ? new_peak_of(p) : p; };
    steps_.desaturation = [](double p) { return p >= double(kStart) ? 1.0 - desaturation_of(p, new_peak_of(p)) : 1.0; };
  }
  const HueKeepingSteps* hue_keeping_steps() const override { return &steps_; }
  // Over planes so that the loop vectorises (apply_in_planes): the compression is computed for
  // every pixel and kept where peak >= start, the same arithmetic as the branch it replaces;
  // min and max keep std::min/max({...})'s order, so NaN is treated as before.
  void apply(float* px, std::size_t count, std::size_t stride) const override {
    apply_in_planes(px, count, stride, clamp_output, [](float* r, float* g, float* b, std::size_t n) {
      for (std::size_t j = 0; j < n; ++j) {
        float c0 = std::max(r[j], 0.f), c1 = std::max(g[j], 0.f), c2 = std::max(b[j], 0.f);
        float x = c0;
        x = c1 < x ? c1 : x;
        x = c2 < x ? c2 : x;
        const float offset = offset_of(x);
        c0 -= offset;
        c1 -= offset;
        c2 -= offset;
        float peak = c0;
        peak = peak < c1 ? c1 : peak;
        peak = peak < c2 ? c2 : peak;
        const float new_peak = new_peak_of(peak);
        const float s = new_peak / peak;
        const float gd = desaturation_of(peak, new_peak);
        const bool compress = peak >= kStart;
        r[j] = compress ? c0 * s + (new_peak - c0 * s) * gd : c0;
        g[j] = compress ? c1 * s + (new_peak - c1 * s) * gd : c1;
        b[j] = compress ? c2 * s + (new_peak - c2 * s) * gd : c2;
      }
    });
  }

 private:
  HueKeepingSteps steps_;
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
