#pragma once
// Internal to filters/: the SIMD kernels of the fast (two_scale.cpp), separable and Poisson
// evaluations, written once (simd_kernels.inc) and compiled per instruction set
// (simd_kernels_<isa>.cpp); util/simd.h chooses which one runs.
#include "cgtmo/filters/guide.h"
#include "cgtmo/util/simd.h"

namespace cgtmo::filters::simd_kernels {

struct Guide9 {
  const float* g[9];
};

// The nodes of the two-scale evaluation (see simd_kernels.inc).
struct NodePlanes {
  const float* px;
  const float* py;
  const float* g[9];
  const float* kpos;
  const float* sum;
  const float* mass;
  int pitch;
};

// One prepared fine row (two_scale.cpp's FineRow): guide channels (zero at invalid pixels), validity
// (1 or 0) and log luminance, readable to the row's width rounded up to the vector width plus one
// vector.
struct RowPlanes {
  const float* g[9];
  const float* valid;  // nullptr: the row is outside the frame
  const float* lum;
};

// Stage A's surface test for one fine row (simd_kernels.inc, share_row): per pixel, the factor on its
// gathering weights and the exponent bound of its own surface's nodes; factor == nullptr: no test.
struct ShareRow {
  const float* factor;
  const float* limit;
  float relax;
};

// The Poisson-disk offsets as the SIMD evaluation reads them.
struct PoissonOffsets {
  const int* dx;
  const int* dy;
  int count;
};

struct Kernels {
  const char* name;  // simd::isa_name(): "baseline", "avx2", "avx512"
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
                       const float* const node_rows[3][14], float kn, float ka, float min_weight, float ridge,
                       float max_spread2, float min_mass, float* out, float* need);
  // Stage C's fallback at pixel x of row y: the definition over the fine rows near_rows (row
  // near_y0 + t, columns [near_x0, near_x1]) and the nodes of the cells beyond near_cells, out to
  // far_radius cells (simd_kernels.inc, direct_pixel). cg: x's guide, kp: its position coefficient
  // (* log2 e), kn/ka (* log2 e), spatial: -log2e / (2 sigma_g^2).
  float (*direct_pixel)(unsigned groups, int x, int y, int near_x0, int near_x1, int near_y0, int near_count,
                        const RowPlanes* near_rows, const NodePlanes& nodes, int centre, int near_cells, int far_radius,
                        const float* cg, float kp, float kn, float ka, float spatial);
  // The Poisson-disk evaluation at output pixels [x0, x0 + width of a vector) of row y
  // (simd_kernels.inc, poisson_block).
  void (*poisson_block)(unsigned groups, int x0, int y, int width, int height, const PoissonOffsets& offsets,
                        const Guide9& g, const float* valid, const float* lum, const float* kpos, float kn, float ka,
                        float* out);
  // Stage A (simd_kernels.inc): the weight of each pixel of a fine row towards its cell's
  // representative; one fine row's share of a node row's gathering.
  void (*aggregate_row)(unsigned groups, int width, int scale, const float* const fine_g[9], const float* fine_valid,
                        const float* const rep_g[9], const float* rep_kpos, float kn, float ka, float* weight);
  void (*gather_row)(unsigned groups, int width, int scale, const float* const fine_g[9], const float* fine_valid,
                     const float* fine_lum, const float* const rep_g[9], const float* rep_kpos, float kn, float ka, float tv,
                     float y, const float* const spline[3], const ShareRow& share, float* const acc[9], float* const box[13]);
  void (*share_row)(unsigned groups, int width, int scale, const float* const fine_g[9], const float* fine_valid,
                    const float* const rows[3][11], const float sy[3], const float* const spline[3], float kn, float ka,
                    float relax, float log_ratio, float* factor, float* limit);
  // n interleaved triples src[3x + c] into d0, d1, d2; valid[x] = 0 where one is not finite.
  void (*split_triples)(const float* src, int n, float* d0, float* d1, float* d2, float* valid);
};

Kernels baseline();
#if CGTMO_SIMD_X86
Kernels avx2();
Kernels avx512();
#endif
// The kernels of simd::active() (the CPU's widest, capped by CGTMO_ISA).
const Kernels& best();

}  // namespace cgtmo::filters::simd_kernels
