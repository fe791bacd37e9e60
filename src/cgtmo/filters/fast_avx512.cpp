// The fast filter's passes for avx512 (16 floats per vector); see fast_kernel.inc.
#include "cgtmo/filters/fast_isa.h"
#include "cgtmo/util/target_region.h"

CGTMO_TARGET_BEGIN("avx512f,avx512vl,avx512dq,avx2,fma")
namespace cgtmo::filters::fast_avx512 {
using fast_isa::Guide9;
using fast_isa::NodePlanes;
using fast_isa::RowPlanes;
using fast_isa::PoissonOffsets;
using fast_isa::ShareRow;
#define CGTMO_FAST_WIDTH 16
#include "cgtmo/filters/fast_kernel.inc"
#undef CGTMO_FAST_WIDTH
}  // namespace cgtmo::filters::fast_avx512
CGTMO_TARGET_END()

namespace cgtmo::filters::fast_isa {
Kernels avx512() { return Kernels{"avx512", 16, &fast_avx512::run_pass_h, &fast_avx512::run_pass_v,
                 &fast_avx512::run_coarse_row, &fast_avx512::run_upsample_row, &fast_avx512::run_direct_pixel, &fast_avx512::run_poisson_block,
                 &fast_avx512::run_aggregate_row, &fast_avx512::run_gather_row, &fast_avx512::run_share_row, &fast_avx512::split_triples}; }
}  // namespace cgtmo::filters::fast_isa
