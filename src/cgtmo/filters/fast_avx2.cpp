// The fast filter's passes for avx2 (8 floats per vector); see fast_kernel.inc.
#include "cgtmo/filters/fast_isa.h"
#include "cgtmo/util/target_region.h"

CGTMO_TARGET_BEGIN("avx2,fma")
namespace cgtmo::filters::fast_avx2 {
using fast_isa::Guide9;
using fast_isa::NodePlanes;
using fast_isa::RowPlanes;
using fast_isa::PoissonOffsets;
using fast_isa::ShareRow;
#define CGTMO_FAST_WIDTH 8
#include "cgtmo/filters/fast_kernel.inc"
#undef CGTMO_FAST_WIDTH
}  // namespace cgtmo::filters::fast_avx2
CGTMO_TARGET_END()

namespace cgtmo::filters::fast_isa {
Kernels avx2() { return Kernels{"avx2", 8, &fast_avx2::run_pass_h, &fast_avx2::run_pass_v,
                 &fast_avx2::run_coarse_row, &fast_avx2::run_upsample_row, &fast_avx2::run_direct_pixel, &fast_avx2::run_poisson_block,
                 &fast_avx2::run_aggregate_row, &fast_avx2::run_gather_row, &fast_avx2::run_share_row, &fast_avx2::split_triples}; }
}  // namespace cgtmo::filters::fast_isa
