#pragma once
// The G-buffer cross-bilateral filter of CG-TMO (Banterle et al., EUSIPCO 2014, Eq. 3-4, n = 3):
// one definition, several evaluations that share one signature shape
//     void cross_bilateral_<method>(const GuidedInput& in, const FilterParams& p, float* out);
//
// The definition. For a pixel x that holds geometry (mask > 0.5):
//     base(x) = sum_y w(x,y) L(y) / sum_y w(x,y),   y valid and |y - x|_inf <= R,
//     w(x,y)  = exp(-|x-y|^2      / (2 sigma_g^2))              spatial, in pixels
//             * exp(-|P(x)-P(y)|^2 / (2 sigma_pos(x)^2))        world position
//             * exp(-|N(x)-N(y)|^2 / (2 sigma_n^2))             normal (as stored, not renormalised)
//             * exp(-|A(x)-A(y)|^2 / (2 sigma_albedo^2))        albedo
// with L the log10 luminance, sigma_pos(x) = footprint(x) * sigma_pos_footprints (the world size of
// one pixel at x times sigma_g in the paper), and R = ceil(window_sigmas * sigma_g).
// A guide group that is not active (FilterParams::groups) contributes no factor.
// Background (mask <= 0.5, or any non-finite value among the channels read) is never a source y,
// and its own output is its input: base(x) = L(x), so the operator is global there.
//
// Evaluations (one file each; filter_table.h lists them by name, with wls.h's WLS):
//   exact      the definition above, double accumulation: the reference (slow).
//   poisson    the paper's approximation: S offsets, Poisson-disk distributed with Gaussian density;
//              SIMD over neighbouring pixels, which share each offset (simd_kernels.inc).
//   fast       two scales: the filter between s x s cell representatives, then a G-buffer-guided
//              upsampling, and the definition itself (float, SIMD, a 3-sigma window whose far
//              cells come from their nodes) at the pixels the coarse level does not describe
//              (two_scale.cpp).
//   separable  horizontal then vertical 1-D passes in homogeneous coordinates (separable.cpp).
//   bilateral  the classic bilateral of L alone (no G-buffer), the paper's Figure 3(a).
// All are parallel over rows with util/parallel.h and allocate nothing per pixel.
#include <cstddef>
#include <string>
#include <vector>

namespace cgtmo::filters {

// One float32 channel: element i is data[i * stride] (stride 3 reads one component of xyz planes).
struct Channel {
  const float* data = nullptr;
  int stride = 1;
  explicit operator bool() const { return data != nullptr; }
  float operator[](std::size_t i) const { return data[i * std::size_t(stride)]; }
};

// The inputs, borrowed (nothing is copied unless an evaluation needs a layout of its own).
struct GuidedInput {
  int width = 0, height = 0;
  Channel log_lum;       // log10 luminance (floored by the caller): the signal
  Channel position[3];   // world-space position
  Channel normal[3];     // world-space normal
  Channel albedo[3];     // diffuse albedo (linear RGB)
  Channel mask;          // > 0.5: geometry. Absent: every pixel is geometry
  Channel footprint;     // world size of one pixel at each pixel. Absent: FilterParams::footprint

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
};

// The guide groups of Eq. 4, as bits, so a frame whose albedo is uniform runs without it.
enum GuideGroup : unsigned {
  kGuidePosition = 1u,
  kGuideNormal = 2u,
  kGuideAlbedo = 4u,
  kGuideAll = 7u,
};
std::string describe_groups(unsigned groups);  // "position+normal+albedo", "none"

// The knobs of `fast` (two_scale.cpp): the coarse level of cell representatives, and the tests
// that judge whether the nodes around a pixel describe it; a pixel they do not describe is
// evaluated directly, by the definition.
struct TwoScaleParams {
  // Cell size of the coarse level in pixels (2..8; 0: fast_cell_size's default, 3).
  int cell_size = 0;
  // The total weight below which the nodes around a pixel are judged not to describe it.
  float min_weight = 1.0f;
  int direct_radius = 0;  // window radius (pixels) of the pixels evaluated directly; 0: fast_radius(p)
  // The direct evaluation sums the definition over the fine pixels of the cells within this many
  // pixels of the pixel's cell, and takes the cells beyond from their nodes (weight at the node's
  // centroid and guide); 0: the definition over the whole window. 12 px (4 cells of 3) measured as
  // exact as the whole window on every committed frame (docs/speed-vs-error.md).
  int direct_near = 12;
  // Ridge on the slopes of the plane fitted to the coarse values, in units of cell_size^2.
  float ridge = 0.05f;
  // A pixel whose surrounding nodes' values spread (weighted standard deviation, log10 units) by
  // more than this is evaluated directly too (0: no such test).
  float max_spread = 0.015f;
  // Nodes whose gathered weight is below this fraction of their cell's s^2 pixels (strips thinner
  // than a cell, the last pixels of a surface) do not count towards min_weight.
  float min_node_mass = 0.7f;
  // Nodes whose cell's valid pixels keep less than this fraction of their weight towards the
  // representative in normal and albedo alone (a textured cell: bricks and mortar, bevels) do not
  // count towards min_weight either.
  float min_purity = 0.95f;
  // A cell whose centre pixel keeps less than this fraction of its valid pixels' weight (the
  // centre lies on a crease, a strip, an anti-aliased edge) is represented by its medoid instead
  // (0: always the centre).
  float majority = 0.7f;
  // A pixel among nodes of two surfaces (a silhouette, a crease) is gathered only by those of its
  // own surface: the nodes whose weight for it (position factor relaxed 16-fold) is within this
  // ratio of its best one, when that is at least 1/2; its weight is scaled so that their B-spline
  // weights sum to 1 (0: every node takes it with its own weight).
  float share = 0.05f;
};

struct FilterParams {
  // The paper's parameters.
  float sigma_spatial_px = 8.0f;      // sigma_g
  float sigma_pos_footprints = 8.0f;  // sigma_pos = footprint * this (the paper: footprint * sigma_g)
  float sigma_normal = 0.25f;
  float sigma_albedo = 0.25f;
  float footprint = 0.0f;             // used when GuidedInput::footprint is absent
  unsigned groups = kGuideAll;        // active guide groups (GuideGroup bits)

  // exact / bilateral: window radius in units of sigma_g (at least 3 for the reference).
  float window_sigmas = 3.0f;
  // poisson: number of offsets (the centre pixel is always one of them) and the pattern's seed.
  int poisson_samples = 32;
  unsigned poisson_seed = 1;
  // bilateral: range sigma on log10 luminance (Durand and Dorsey's 0.4).
  float sigma_range_log10 = 0.4f;
  // fast and separable: window radius in units of the effective spatial sigma (sigma_g / sqrt 2
  // on surfaces facing the camera, where the position term acts as a second spatial Gaussian).
  float effective_window_sigmas = 3.0f;
  // fast: the coarse level and the tests that send a pixel to the direct evaluation.
  TwoScaleParams two_scale;
};

// `fast` as it was before its direct-evaluation tests (two scales alone: 2x2 cells, min weight
// 0.3, no spread or node-mass test, an 8 px direct window), for comparison in the benchmark and
// the tests; the other fields come from `base`.
inline FilterParams fast_two_scales_only(FilterParams base = {}) {
  base.two_scale.cell_size = 2;
  base.two_scale.min_weight = 0.3f;
  base.two_scale.max_spread = 0.0f;
  base.two_scale.ridge = 0.05f;
  base.two_scale.direct_radius = 8;
  base.two_scale.min_node_mass = 0.0f;
  base.two_scale.min_purity = 0.0f;
  return base;
}

// Throws UsageError when sizes, pointers or parameters are inconsistent (e.g. an active group
// whose channels are missing, or the position group without any footprint).
void check_input(const GuidedInput& in, const FilterParams& p);

void cross_bilateral_exact(const GuidedInput& in, const FilterParams& p, float* out_base_log);
void cross_bilateral_poisson(const GuidedInput& in, const FilterParams& p, float* out_base_log);
void cross_bilateral_fast(const GuidedInput& in, const FilterParams& p, float* out_base_log);
// `fast` with a count of the pixels it evaluated directly (diagnostics for the benchmark).
void cross_bilateral_fast_counted(const GuidedInput& in, const FilterParams& p, float* out_base_log,
                                  std::size_t* direct_pixels);
// The separable evaluation (an idea measured against `fast`; see separable.cpp and docs/speed-vs-error.md).
void cross_bilateral_separable(const GuidedInput& in, const FilterParams& p, float* out_base_log);
// The separable evaluation's 1-D window radius in pixels for these parameters.
int fast_radius(const FilterParams& p);
// The cell size `fast` uses on a width x height frame: two_scale.cell_size, or 3 when 0. With the direct
// evaluation of the pixels the nodes do not describe, s=3 was both faster and closer to `exact`
// than s=2 on the 1920x1080 frame and on the committed scenes (docs/speed-vs-error.md).
int fast_cell_size(const FilterParams& p, int width, int height);
// Classic bilateral of log luminance: only log_lum, mask and the spatial/range sigmas are used.
void cross_bilateral_bilateral(const GuidedInput& in, const FilterParams& p, float* out_base_log);

// The shape every evaluation above shares; filter_table.h lists them by name.
using FilterFunction = void (*)(const GuidedInput&, const FilterParams&, float*);

// Which guide groups carry information in this frame. A group is dropped when, over the valid
// pixels, every channel's spread (max - min) is below `relative_threshold` times its sigma: then
// every weight of that group is at least exp(-3 t^2 / 2) (0.9963 for the default t = 0.05), so
// dropping it changes no weight by more than 0.4%.
struct GuideAnalysis {
  unsigned informative = 0;  // GuideGroup bits
  float spread[3] = {0, 0, 0};  // largest per-channel spread of position / normal / albedo
  float sigma[3] = {0, 0, 0};   // the sigma each spread was compared with (position: the median sigma_pos)
  std::string explain;          // one line per group: kept or dropped, and why
};
GuideAnalysis analyze_guide(const GuidedInput& in, const FilterParams& p, float relative_threshold = 0.05f);

// World size of one pixel, from the position buffer alone: at each valid pixel, the smallest
// distance to a valid 4-neighbour (the least foreshortened direction; a silhouette has a large
// jump on one side only). Pixels with no valid neighbour get the frame's median footprint.
std::vector<float> footprint_from_positions(const GuidedInput& in);

// Root-mean-square difference over the pixels where mask > 0.5 (all pixels when absent), in the
// planes' units (log10 luminance here).
double rmse_valid(const float* a, const float* b, const GuidedInput& in);

}  // namespace cgtmo::filters
