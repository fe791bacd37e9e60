// The filters' SIMD kernels for the baseline instruction set (4 floats per vector, generic
// vector code: SSE2 on x86-64, whatever the target has elsewhere), and the run-time choice.
#include "cgtmo/filters/simd_kernels.h"

namespace cgtmo::filters::kernels_baseline {
using simd_kernels::Guide9;
using simd_kernels::NodePlanes;
using simd_kernels::RowPlanes;
using simd_kernels::PoissonOffsets;
using simd_kernels::ShareRow;
#define CGTMO_KERNEL_WIDTH 4
#include "cgtmo/filters/simd_kernels.inc"
#undef CGTMO_KERNEL_WIDTH
}  // namespace cgtmo::filters::kernels_baseline

namespace cgtmo::filters::simd_kernels {
Kernels baseline() {
  return Kernels{simd::isa_name(simd::Isa::Baseline), 4,
                 &kernels_baseline::run_pass_h,
                 &kernels_baseline::run_pass_v,
                 &kernels_baseline::run_coarse_row,
                 &kernels_baseline::run_upsample_row,
                 &kernels_baseline::run_direct_pixel,
                 &kernels_baseline::run_poisson_block,
                 &kernels_baseline::run_aggregate_row,
                 &kernels_baseline::run_gather_row,
                 &kernels_baseline::run_share_row,
                 &kernels_baseline::split_triples};
}

const Kernels& best() {
  static const Kernels chosen = [] {
    switch (simd::active()) {
#if CGTMO_SIMD_X86
      case simd::Isa::Avx512: return avx512();
      case simd::Isa::Avx2: return avx2();
#endif
      default: return baseline();
    }
  }();
  return chosen;
}
}  // namespace cgtmo::filters::simd_kernels
