#pragma once
// Internal to filters/fast.cpp: the two passes of the fast filter compiled per instruction set
// (fast_kernel.inc), chosen at run time from what the CPU supports.
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters::fast_isa {

struct Guide9 {
  const float* g[9];
};

// The nodes of the two-scale evaluation (see fast_kernel.inc).
struct NodePlanes {
  const float* px;
  const float* py;
  const float* g[9];
  const float* kpos;
  const float* sum;
  const float* mass;
  int pitch;
};

struct Kernels {
  const char* name;  // "sse2", "avx2", "avx512"
  int width;         // floats per vector
  void (*pass_h)(unsigned groups, int width, int radius, const float* spatial, const float* lm, const float* m,
                 const Guide9& g, const float* kpos, float kn, float ka, float* num, float* den);
  void (*pass_v)(unsigned groups, int width, int pitch, int radius, const float* spatial, const float* const* g_rows[9],
                 const float* const* num_rows, const float* const* den_rows, const float* kpos, float kn, float ka,
                 const float* lum, float* out);
  void (*coarse_row)(unsigned groups, int count, int radius, float spatial, const NodePlanes& n, int row0, float kn,
                     float ka, float* num, float* den);
  void (*upsample_row)(unsigned groups, int width, int scale, int y, int row_of_first, float spatial, const float* const fine_g[9],
                       const float* fine_kpos, const float* fine_lum, const float* fine_valid,
                       const float* const node_rows[3][13], float kn, float ka, float min_weight, float ridge, float* out,
                       float* need);
  void (*aggregate_row)(unsigned groups, int width, int scale, const float* const fine_g[9], const float* fine_valid,
                        const float* const rep_g[9], const float* rep_kpos, float kn, float ka, float* weight);
};

Kernels sse2();
Kernels avx2();
Kernels avx512();
// The widest the CPU runs; CGTMO_FAST_ISA=sse2|avx2|avx512 in the environment overrides (tests).
const Kernels& best();

}  // namespace cgtmo::filters::fast_isa
