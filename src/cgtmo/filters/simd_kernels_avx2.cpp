// The filters' SIMD kernels for avx2 (8 floats per vector); see simd_kernels.inc.
#include "cgtmo/filters/simd_kernels.h"

#if CGTMO_SIMD_X86
CGTMO_SIMD_TARGET_BEGIN(CGTMO_SIMD_AVX2_TARGET)
namespace cgtmo::filters::kernels_avx2 {
using simd_kernels::Guide9;
using simd_kernels::NodePlanes;
using simd_kernels::RowPlanes;
using simd_kernels::PoissonOffsets;
using simd_kernels::ShareRow;
#define CGTMO_KERNEL_WIDTH 8
#include "cgtmo/filters/simd_kernels.inc"
#undef CGTMO_KERNEL_WIDTH
}  // namespace cgtmo::filters::kernels_avx2
CGTMO_SIMD_TARGET_END()

namespace cgtmo::filters::simd_kernels {
Kernels avx2() {
  return Kernels{simd::isa_name(simd::Isa::Avx2), 8,
                 &kernels_avx2::run_pass_h,
                 &kernels_avx2::run_pass_v,
                 &kernels_avx2::run_coarse_row,
                 &kernels_avx2::run_upsample_row,
                 &kernels_avx2::run_direct_pixel,
                 &kernels_avx2::run_poisson_block,
                 &kernels_avx2::run_aggregate_row,
                 &kernels_avx2::run_gather_row,
                 &kernels_avx2::run_share_row,
                 &kernels_avx2::split_triples};
}
}  // namespace cgtmo::filters::simd_kernels
#endif
