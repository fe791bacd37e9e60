// The filters' SIMD kernels for avx512 (16 floats per vector); see simd_kernels.inc.
#include "cgtmo/filters/simd_kernels.h"

#if CGTMO_SIMD_X86
CGTMO_SIMD_TARGET_BEGIN(CGTMO_SIMD_AVX512_TARGET)
namespace cgtmo::filters::kernels_avx512 {
using simd_kernels::Guide9;
using simd_kernels::NodePlanes;
using simd_kernels::RowPlanes;
using simd_kernels::PoissonOffsets;
using simd_kernels::ShareRow;
#define CGTMO_KERNEL_WIDTH 16
#include "cgtmo/filters/simd_kernels.inc"
#undef CGTMO_KERNEL_WIDTH
}  // namespace cgtmo::filters::kernels_avx512
CGTMO_SIMD_TARGET_END()

namespace cgtmo::filters::simd_kernels {
Kernels avx512() {
  return Kernels{simd::isa_name(simd::Isa::Avx512), 16,
                 &kernels_avx512::run_pass_h,
                 &kernels_avx512::run_pass_v,
                 &kernels_avx512::run_coarse_row,
                 &kernels_avx512::run_upsample_row,
                 &kernels_avx512::run_direct_pixel,
                 &kernels_avx512::run_poisson_block,
                 &kernels_avx512::run_aggregate_row,
                 &kernels_avx512::run_gather_row,
                 &kernels_avx512::run_share_row,
                 &kernels_avx512::split_triples};
}
}  // namespace cgtmo::filters::simd_kernels
#endif
