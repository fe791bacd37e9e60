#include "cgtmo/operators/curve_table.h"
#include "cgtmo/util/target_region.h"

#include <immintrin.h>

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

// The pipeline for the baseline instruction set (SSE2 on x86-64).
namespace curve_table_baseline {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 0
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_baseline

// The same source for AVX2 + FMA, with the table read by gathers.
CGTMO_TARGET_BEGIN("avx2,fma")
namespace curve_table_avx2 {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 1
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_avx2
CGTMO_TARGET_END()

// Where AVX-512 exists: the per-channel pipelines over 16 pixels (CGTMO_CURVE_AVX512), the rest
// as for AVX2 (with 32 vector registers).
CGTMO_TARGET_BEGIN("avx2,fma,avx512f,avx512vl,avx512dq,avx512bw")
namespace curve_table_avx512 {
using namespace curve_table_detail;
#define CGTMO_CURVE_AVX2 1
#define CGTMO_CURVE_AVX512 1
#include "cgtmo/operators/curve_table_kernel.inc"
#undef CGTMO_CURVE_AVX512
#undef CGTMO_CURVE_AVX2
}  // namespace curve_table_avx512
CGTMO_TARGET_END()

namespace {

bool use_avx2() {
  static const bool yes = [] {
    const char* env = std::getenv("CGTMO_CURVE_ISA");
    if (env && std::string(env) == "scalar") return false;
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return yes;
}

bool use_avx512() {
  static const bool yes = [] {
    const char* env = std::getenv("CGTMO_CURVE_ISA");
    if (env && *env && std::string(env) != "avx512") return false;
    __builtin_cpu_init();
    return use_avx2() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
  }();
  return yes;
}

}  // namespace

float CurveTable::node_x(std::size_t k) {
  const uint32_t b = curve_table_detail::kLowBits + (uint32_t(k) << curve_table_detail::kFractionBits);
  float x;
  std::memcpy(&x, &b, 4);
  return x;
}

bool CurveTable::eval(const float* in, float* out, std::size_t n) const {
  if (use_avx2()) return curve_table_avx2::lookup(*this, in, out, n);
  return curve_table_baseline::lookup(*this, in, out, n);
}

const char* CurveTable::isa() { return use_avx512() ? "avx512" : use_avx2() ? "avx2" : "scalar"; }

void apply_curve(const CurveApply& a, float* px, std::size_t count, std::size_t stride) {
  if (use_avx512()) return curve_table_avx512::apply_curve_impl(a, px, count, stride);
  if (use_avx2()) return curve_table_avx2::apply_curve_impl(a, px, count, stride);
  return curve_table_baseline::apply_curve_impl(a, px, count, stride);
}

void planes_from_pixels(const float* px, std::size_t n, std::size_t stride, float* r, float* g, float* b) {
  if (use_avx2()) return curve_table_avx2::load_planes(px, n, stride, r, g, b);
  return curve_table_baseline::load_planes(px, n, stride, r, g, b);
}

void pixels_from_planes(const float* r, const float* g, const float* b, std::size_t n, bool clamp, float* px,
                        std::size_t stride) {
  if (use_avx2()) return curve_table_avx2::store_planes(r, g, b, n, clamp, px, stride);
  return curve_table_baseline::store_planes(r, g, b, n, clamp, px, stride);
}

}  // namespace cgtmo::operators
