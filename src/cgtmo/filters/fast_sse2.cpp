// The fast filter's passes for sse2 (4 floats per vector); see fast_kernel.inc.
#include "cgtmo/filters/fast_isa.h"

namespace cgtmo::filters::fast_sse2 {
using fast_isa::Guide9;
using fast_isa::NodePlanes;
using fast_isa::RowPlanes;
using fast_isa::PoissonOffsets;
using fast_isa::ShareRow;
#define CGTMO_FAST_WIDTH 4
#include "cgtmo/filters/fast_kernel.inc"
#undef CGTMO_FAST_WIDTH
}  // namespace cgtmo::filters::fast_sse2

namespace cgtmo::filters::fast_isa {
Kernels sse2() { return Kernels{"sse2", 4, &fast_sse2::run_pass_h, &fast_sse2::run_pass_v,
                 &fast_sse2::run_coarse_row, &fast_sse2::run_upsample_row, &fast_sse2::run_direct_pixel, &fast_sse2::run_poisson_block,
                 &fast_sse2::run_aggregate_row, &fast_sse2::run_gather_row, &fast_sse2::run_share_row, &fast_sse2::split_triples}; }
}  // namespace cgtmo::filters::fast_isa
