#pragma once
// The filters' input for a scene (filters::GuidedInput), built one way for `cgtmo apply`
// (tone_map_local), the benchmark and the tests:
//   - the signal: log10 of the luminance (or illumination) floored at 1e-4 Lw_a (log_floor_of);
//   - the mask: 0 on background (the reader's mask, from depth) and where the normal has no
//     direction; those pixels are neither sources nor filtered. No mask plane when neither occurs
//     and the render has no depth (every pixel is geometry);
//   - the normals as the reader renormalised them (a hand-built scene's are renormalised here);
//   - position and albedo as stored; the footprint from depth and the sidecar camera, else from
//     neighbouring positions.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "cgtmo/filters/guide.h"
#include "cgtmo/local/local_drago.h"
#include "cgtmo/scene/frame.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::local {

// Luminances below this fraction of Lw_a are floored before the log: Drago's curve shows them
// as black anyway, and the floor keeps black pixels from dragging their neighbours' base down.
inline constexpr double kLogFloorRelative = 1e-4;
double log_floor_of(double lw_a);
// The signal's value for a luminance (or illumination) v.
inline float floored_log10(double v, double floor) { return float(repro::log10(std::max(v, floor))); }

// Rec.709 luminance of the beauty, non-finite and negative as 0.
std::vector<float> beauty_luminance(const scene::Frame& scene);

// The planes the filters read and the GuidedInput that points into them (and into the scene's
// position, albedo and, unless renormalised here, normal planes: the scene must outlive it).
// Movable, not copyable: the pointers follow the planes.
struct FilterInput {
  std::vector<float> log_lum, mask, footprint;
  std::vector<float> normal;  // a renormalised copy, only when the scene's normals are not unit
  filters::GuidedInput input;
  unsigned available = 0;               // filters::GuideGroup bits the render has
  std::size_t background = 0;           // background pixels (from depth)
  double background_fraction = 0;
  std::size_t invalid_normals = 0;      // geometry pixels whose normal has no direction (masked)
  std::vector<std::string> lines;       // for --explain: background, footprint and normal notes

  FilterInput() = default;
  FilterInput(FilterInput&&) = default;
  FilterInput& operator=(FilterInput&&) = default;
  FilterInput(const FilterInput&) = delete;
  FilterInput& operator=(const FilterInput&) = delete;

  // Frees the planes (the pipeline's peak memory); `input` is unusable afterwards.
  void release();
};

// `log_lum`: the signal, width*height floored log10 values.
FilterInput build_filter_input(const scene::Frame& scene, std::vector<float> log_lum);

// What tone_map_local filters for `options` with detail=luminance: the beauty's luminance, the
// scene statistics' Lw_a (or options.lw_a when given) for the floor, then build_filter_input.
// For the benchmark and the tests; `lw_a` (optional) receives the Lw_a used.
FilterInput luminance_filter_input(const scene::Frame& scene, const LocalOptions& options = {}, double* lw_a = nullptr);

}  // namespace cgtmo::local
