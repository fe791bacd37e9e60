#pragma once
// One run-time choice of instruction set for every SIMD kernel of the library (the curve table's
// pipelines, the cross-bilateral filters' passes): one CPU detection, one feature set per level,
// one environment variable.
//
// Levels: baseline (what the compiler targets by default; on x86-64, SSE2), avx2 (AVX2 + FMA) and
// avx512 (AVX2 + FMA + AVX-512 F, VL, DQ, BW). CGTMO_ISA=baseline|avx2|avx512 caps the level (the
// tests run once per level through it); unset, the widest the CPU runs is used.
//
// A build configured with -DCGTMO_SIMD=OFF, or for a CPU other than x86-64, compiles the baseline
// kernels only: CGTMO_SIMD_X86 is then 0 and nothing below targets another instruction set.
#include <vector>

namespace cgtmo::simd {

enum class Isa { Baseline = 0, Avx2 = 1, Avx512 = 2 };

const char* isa_name(Isa isa);  // "baseline", "avx2", "avx512"

// Whether this build holds kernels for `isa` (baseline: always).
bool compiled(Isa isa);
// Whether this build holds them and the CPU runs them.
bool available(Isa isa);
// Every available level, narrowest first.
std::vector<Isa> available_isas();
// The level the kernels run: the widest available one, capped by CGTMO_ISA (read once). An
// unknown CGTMO_ISA value is ignored with a one-line warning on stderr.
Isa active();

}  // namespace cgtmo::simd

#ifndef CGTMO_SIMD_X86
#define CGTMO_SIMD_X86 0
#endif

#if CGTMO_SIMD_X86
// The feature sets as compiler targets, for the kernels' regions: the same strings that active()
// checks on the CPU (simd.cpp), so a level never runs code built for features it did not check.
#define CGTMO_SIMD_AVX2_TARGET "avx2,fma"
#define CGTMO_SIMD_AVX512_TARGET "avx2,fma,avx512f,avx512vl,avx512dq,avx512bw"

// Compile a region of a file for one of those targets, with GCC (the release build) and clang (the
// sanitizer and fuzz build) alike:
//   CGTMO_SIMD_TARGET_BEGIN(CGTMO_SIMD_AVX2_TARGET) ... CGTMO_SIMD_TARGET_END()
// Code in the region runs only when active() says the CPU has those features.
#define CGTMO_SIMD_PRAGMA(x) _Pragma(#x)
#if defined(__clang__)
#define CGTMO_SIMD_TARGET_BEGIN(isa) \
  CGTMO_SIMD_PRAGMA(clang attribute push(__attribute__((target(isa))), apply_to = function))
#define CGTMO_SIMD_TARGET_END() CGTMO_SIMD_PRAGMA(clang attribute pop)
#else
#define CGTMO_SIMD_TARGET_BEGIN(isa) CGTMO_SIMD_PRAGMA(GCC push_options) CGTMO_SIMD_PRAGMA(GCC target(isa))
#define CGTMO_SIMD_TARGET_END() CGTMO_SIMD_PRAGMA(GCC pop_options)
#endif
#endif
