#pragma once
// A ray-cast test scene with a G-buffer, for the filters' tests and for benchmarks before (or
// without) Blender renders: a room (checkered floor, coloured walls) with two spheres, a point
// light with shadows, a hole in the back wall onto background, and optional multiplicative
// Monte-Carlo-like noise. Deterministic for given arguments.
#include <vector>

#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

struct SyntheticScene {
  int width = 0, height = 0;
  std::vector<float> log_lum, mask, footprint;
  std::vector<float> position[3], normal[3], albedo[3];
  GuidedInput view() const;  // borrows this scene's planes
};

// noise_log10: standard deviation of the per-pixel noise, in log10 units (0: noise-free).
SyntheticScene make_synthetic_scene(int width, int height, float noise_log10 = 0.05f, unsigned seed = 1);

}  // namespace cgtmo::filters
