#pragma once
// A committed render as the filters' input, for the benchmark and the filters' scene tests: the
// scene reader's planes (cgtmo/scene_load.h) turned into filters::GuidedInput the way the CG-TMO
// pipeline does it (cgtmo/local_drago.cpp): log10 luminance with a floor, background from depth,
// renormalised normals (zero-length ones invalid), footprint from depth and the sidecar camera
// (else from neighbouring positions).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cgtmo/local/scene_load.h"
#include "cgtmo/color/luminance.h"
#include "cgtmo/filters/guide.h"

namespace cgtmo::bench {

struct GuideFrame {
  local::SceneData scene;
  std::vector<float> log_lum, mask, normal, footprint;
  filters::GuidedInput input;
  std::size_t channels_read = 0;  // float32 channels taken from the file (beauty + G-buffer + depth)
};

inline void load_guide_frame(const std::string& path, GuideFrame& f) {
  local::LoadRequest req;
  req.path = path;
  req.needed_by = "bench";
  req.light_groups = false;
  req.probe = false;
  f.scene = local::load_scene(req).scene;
  const local::SceneData& s = f.scene;
  const std::size_t n = s.pixel_count();
  f.channels_read = 3 + (s.position.empty() ? 0 : 3) + (s.normal.empty() ? 0 : 3) + (s.albedo.empty() ? 0 : 3) +
                    (s.depth.empty() ? 0 : 1);
  f.mask.assign(n, 1.0f);
  if (!s.depth.empty())
    for (std::size_t i = 0; i < n; ++i)
      f.mask[i] = std::isfinite(s.depth[i]) && s.depth[i] < local::kBackgroundDepth ? 1.0f : 0.0f;
  // Luminance floor: 1e-6 of the mean luminance of the geometry (keeps log10 finite on black).
  double mean = 0.0;
  std::size_t count = 0;
  f.log_lum.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float y = color::luminance(s.rgb[3 * i], s.rgb[3 * i + 1], s.rgb[3 * i + 2]);
    f.log_lum[i] = y;
    if (f.mask[i] > 0.5f) mean += y, ++count;
  }
  const double floor = std::max(1e-12, 1e-6 * (count ? mean / double(count) : 1.0));
  for (auto& v : f.log_lum) v = float(std::log10(std::max(double(v), floor)));
  filters::GuidedInput& in = f.input;
  in.width = s.width;
  in.height = s.height;
  in.log_lum = filters::Channel{f.log_lum.data(), 1};
  in.mask = filters::Channel{f.mask.data(), 1};
  if (!s.normal.empty()) {
    f.normal = s.normal;
    for (std::size_t i = 0; i < n; ++i) {
      float* v = &f.normal[3 * i];
      const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (len >= 0.1f && std::isfinite(len))
        v[0] /= len, v[1] /= len, v[2] /= len;
      else
        v[0] = v[1] = v[2] = std::nanf("");
    }
    for (int k = 0; k < 3; ++k) in.normal[k] = filters::Channel{f.normal.data() + k, 3};
  }
  if (!s.albedo.empty())
    for (int k = 0; k < 3; ++k) in.albedo[k] = filters::Channel{s.albedo.data() + k, 3};
  if (!s.position.empty()) {
    for (int k = 0; k < 3; ++k) in.position[k] = filters::Channel{s.position.data() + k, 3};
    if (s.footprint_at_1m > 0 && !s.depth.empty()) {
      f.footprint.resize(n);
      for (std::size_t i = 0; i < n; ++i) f.footprint[i] = float(double(s.depth[i]) * s.footprint_at_1m);
    } else {
      f.footprint = filters::footprint_from_positions(in);
    }
    in.footprint = filters::Channel{f.footprint.data(), 1};
  }
}

// The guide groups this frame has.
inline unsigned available_groups(const filters::GuidedInput& in) {
  return (in.position[0] ? filters::kGuidePosition : 0u) | (in.normal[0] ? filters::kGuideNormal : 0u) |
         (in.albedo[0] ? filters::kGuideAlbedo : 0u);
}

}  // namespace cgtmo::bench
