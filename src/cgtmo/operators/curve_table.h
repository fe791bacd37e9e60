#pragma once
// The fast float evaluation of a scalar tone curve: a table of the exact (double) curve with
// 1024 nodes per octave over [2^-24, 2^16), linearly interpolated. Node k sits at the float whose
// bits are bits(2^-24) + k * 2^13, so the node index and the interpolation weight are the high and
// low bits of the input's bit pattern (no log, no search), and within one octave the nodes are
// evenly spaced in x, so interpolation is linear in x. Below 2^-24 the curve is the straight line
// from f(0) to f(2^-24). Inputs of 2^16 and above, and NaN, are outside: eval() reports them and
// the caller evaluates them exactly. The measured error against the exact curve is in
// docs/performance.md (bench/curve_error.cpp measures it).
//
// apply_curve() runs the whole per-pixel pipeline of a curve operator over blocks of pixels split
// into planes (so that it vectorises), compiled for the baseline, AVX2 and AVX-512 levels of
// util/simd.h, chosen at run time; the curve-specific exact fallbacks are callbacks, called only where the table cannot serve.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cgtmo::operators {

class CurveTable {
 public:
  static constexpr int kNodesPerOctaveLog2 = 10;
  static constexpr int kLowExponent = -24, kHighExponent = 16;
  static constexpr float kLow = 0x1p-24f;   // first node
  static constexpr float kHigh = 0x1p16f;   // inputs >= this are outside the table
  static constexpr std::size_t kNodes = std::size_t(kHighExponent - kLowExponent) << kNodesPerOctaveLog2;

  // `exact(x)` for x in [0, 2^16]; called kNodes + 2 times, here only.
  template <class F>
  explicit CurveTable(F&& exact) : nodes_(kNodes + 1), pairs_(2 * kNodes) {
    for (std::size_t k = 0; k <= kNodes; ++k) nodes_[k] = float(exact(double(node_x(k))));
    for (std::size_t k = 0; k < kNodes; ++k) {
      pairs_[2 * k] = nodes_[k];
      pairs_[2 * k + 1] = nodes_[k + 1];
    }
    at_zero_ = float(exact(0.0));
    slope_below_ = (nodes_[0] - at_zero_) / kLow;
  }

  // out[i] = curve(in[i]) for 0 <= in[i] < 2^16. Returns false when some in[i] is outside
  // (>= 2^16 or NaN); out[i] is then unspecified there. Uses AVX2 gathers when the CPU has them.
  bool eval(const float* in, float* out, std::size_t n) const;

  // The input of node k (for tests and the error measurement).
  static float node_x(std::size_t k);

  // Which kernels apply_curve() runs: simd::isa_name(simd::active()), "avx512", "avx2" or
  // "baseline" (CGTMO_ISA caps the choice; eval() uses AVX2 at most).
  static const char* isa();

  const float* nodes() const { return nodes_.data(); }
  // Node k and node k + 1 side by side (k < kNodes), so that one 64-bit gather fetches both ends
  // of a segment: half the gathered elements of two 32-bit gathers.
  const float* pairs() const { return pairs_.data(); }
  float at_zero() const { return at_zero_; }
  float slope_below() const { return slope_below_; }

 private:
  std::vector<float> nodes_, pairs_;
  float at_zero_ = 0.f, slope_below_ = 0.f;
};

// One curve operator's pixel pipeline: rgb -> [input matrix] -> curve per channel, or rgb scaled by
// curve(L) / L with L the luminance or max(r, g, b) -> [output matrix] -> [clamp to 0..1].
struct CurveApply {
  enum class Mode { PerChannel, Luminance, MaxRGB };
  const CurveTable* table = nullptr;
  Mode mode = Mode::PerChannel;
  bool saturation_is_one = true;  // false: every pixel goes through exact_scale
  const float* input_matrix = nullptr;   // 9 floats, row-major, or null
  const float* output_matrix = nullptr;  // 9 floats, row-major, or null
  bool clamp = true;
  const void* context = nullptr;
  // The exact curve, for inputs the table does not cover (>= 2^16, NaN).
  float (*exact_curve)(const void* context, float x) = nullptr;
  // Scales rgb so that `in` becomes `out` (saturation, and `in` below 1e-30 where out / in may
  // overflow a float).
  void (*exact_scale)(const void* context, float& r, float& g, float& b, float in, float out) = nullptr;
};

// In place over `count` pixels whose RGB starts every `stride` floats (alpha left alone).
void apply_curve(const CurveApply& a, float* px, std::size_t count, std::size_t stride);

// Interleaved pixels <-> planes (same kernels as apply_curve), for evaluators whose own loop runs
// over planes (see apply_in_planes in curve_evaluator.h). The store clamps to [0, 1] when `clamp`.
void planes_from_pixels(const float* px, std::size_t n, std::size_t stride, float* r, float* g, float* b);
void pixels_from_planes(const float* r, const float* g, const float* b, std::size_t n, bool clamp, float* px,
                        std::size_t stride);

}  // namespace cgtmo::operators
