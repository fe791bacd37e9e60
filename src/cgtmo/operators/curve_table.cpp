#include "cgtmo/operators/curve_table.h"
#include "cgtmo/util/simd.h"

#if CGTMO_SIMD_X86
#include <immintrin.h>
#endif

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cgtmo/color/luminance.h"

namespace cgtmo::operators {
namespace curve_table_detail {

constexpr int kFractionBits = 23 - CurveTable::kNodesPerOctaveLog2;  // mantissa bits below a node
constexpr uint32_t kFractionMask = (1u << kFractionBits) - 1;
constexpr uint32_t kLowBits = uint32_t(127 + CurveTable::kLowExponent) << 23;  // bits of kLow
constexpr float kFractionScale = 1.f / float(1u << kFractionBits);

inline uint32_t bits_of(float x) {
  uint32_t b;
  std::memcpy(&b, &x, 4);
  return b;
}

}  // namespace curve_table_detail

// The pipeline for the baseline instruction set (SSE2 on x86-64; plain loops elsewhere).
namespace curve_table_baseline {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 0
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_baseline

#if CGTMO_SIMD_X86
// The same source for AVX2 + FMA, with the table read by gathers.
CGTMO_SIMD_TARGET_BEGIN(CGTMO_SIMD_AVX2_TARGET)
namespace curve_table_avx2 {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 1
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_avx2
CGTMO_SIMD_TARGET_END()

// Where AVX-512 exists: the per-channel pipelines over 16 pixels (CGTMO_CURVE_AVX512), the rest
// as for AVX2 (with 32 vector registers).
CGTMO_SIMD_TARGET_BEGIN(CGTMO_SIMD_AVX512_TARGET)
namespace curve_table_avx512 {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 1
#define CGTMO_CURVE_AVX512 1
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX512
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_avx512
CGTMO_SIMD_TARGET_END()

#endif

namespace {

// The level the kernels below run (util/simd.h); eval() and the plane conversions use AVX2 at most.
[[maybe_unused]] simd::Isa level() { return simd::active(); }

}  // namespace

float CurveTable::node_x(std::size_t k) {
  const uint32_t b = curve_table_detail::kLowBits + (uint32_t(k) << curve_table_detail::kFractionBits);
  float x;
  std::memcpy(&x, &b, 4);
  return x;
}

bool CurveTable::eval(const float* in, float* out, std::size_t n) const {
#if CGTMO_SIMD_X86
  if (level() >= simd::Isa::Avx2) return curve_table_avx2::lookup(*this, in, out, n);
#endif
  return curve_table_baseline::lookup(*this, in, out, n);
}

const char* CurveTable::isa() { return simd::isa_name(simd::active()); }

void apply_curve(const CurveApply& a, float* px, std::size_t count, std::size_t stride) {
#if CGTMO_SIMD_X86
  if (level() == simd::Isa::Avx512) return curve_table_avx512::apply_curve_impl(a, px, count, stride);
  if (level() == simd::Isa::Avx2) return curve_table_avx2::apply_curve_impl(a, px, count, stride);
#endif
  return curve_table_baseline::apply_curve_impl(a, px, count, stride);
}

void planes_from_pixels(const float* px, std::size_t n, std::size_t stride, float* r, float* g, float* b) {
#if CGTMO_SIMD_X86
  if (level() >= simd::Isa::Avx2) return curve_table_avx2::load_planes(px, n, stride, r, g, b);
#endif
  return curve_table_baseline::load_planes(px, n, stride, r, g, b);
}

void pixels_from_planes(const float* r, const float* g, const float* b, std::size_t n, bool clamp, float* px,
                        std::size_t stride) {
#if CGTMO_SIMD_X86
  if (level() >= simd::Isa::Avx2) return curve_table_avx2::store_planes(r, g, b, n, clamp, px, stride);
#endif
  return curve_table_baseline::store_planes(r, g, b, n, clamp, px, stride);
}

}  // namespace cgtmo::operators
