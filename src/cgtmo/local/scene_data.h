#pragma once
// The CG-TMO pipeline's one scene model: the beauty, the G-buffer planes with the reader's masks,
// the light-group passes, the adaptation probe and the sidecar's lights. Plain data; every plane
// is optional except the beauty, and the pipeline says what it did without a missing one (Explain).
//
// Layering: io::read_scene gives the file's view (io::Scene: a scene::Frame plus windows, channel
// names, companions); load_scene (scene_load.h) turns it into this, moving the Frame's planes and
// masks rather than recomputing them (colour converted, light groups reduced to luminance);
// build_filter_input (filter_input.h) turns this into the filters' input.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "cgtmo/scene/frame.h"

namespace cgtmo::local {

struct LightRecord {
  std::string name, type, group;
  double luminance = std::numeric_limits<double>::quiet_NaN();  // emitted, render units; NaN: unknown
};

struct LightGroupPass {
  std::string name;
  std::vector<float> luminance;  // width*height, Rec.709 Y of the pass
};

struct ProbeData {
  int width = 0, height = 0;     // 64x32 equirectangular, row 0 straight up
  std::vector<float> luminance;  // width*height
  std::string source;
};

// The camera as the sidecar gives it, for view-weighted adaptation (stats.h). World space, Z up.
struct CameraView {
  bool known = false;
  double forward[3] = {0, 0, -1}, right[3] = {1, 0, 0}, up[3] = {0, 1, 0};  // unit vectors
  double fov_x = 0, fov_y = 0;  // full angles of the frame, radians
  // Azimuth (from +X, counter-clockwise seen from above) of the probe's centre column; NaN: the
  // camera's own heading (how scripts/blender/render_scene.py renders the probe).
  double probe_heading = std::numeric_limits<double>::quiet_NaN();
};

struct SceneData {
  int width = 0, height = 0;
  std::vector<float> rgb;       // width*height*3, linear Rec.709, sanitised (scene/sanitize.h)
  std::vector<float> alpha;     // width*height, or empty
  std::vector<float> position;  // xyz interleaved, world space, or empty
  std::vector<float> normal;    // xyz interleaved, world space, or empty; unit or (0,0,0) from the reader
  std::vector<float> albedo;    // rgb interleaved (diffuse colour), or empty
  std::vector<float> depth;     // planar camera depth, background 1e10, or empty
  // The reader's masks (scene::Frame::background, normal_valid), or empty: a scene built by hand
  // goes without, and is_background / has_normal derive them by the reader's rules. Whoever
  // changes depth or normal after loading clears the matching mask.
  std::vector<std::uint8_t> background;    // 1 where no geometry was hit; empty without depth
  std::vector<std::uint8_t> normal_valid;  // 1 where the normal has a direction; empty without normals
  std::vector<LightGroupPass> light_groups;
  ProbeData probe;
  bool has_sidecar = false;
  // Why a companion is absent, naming the file ("'x.json' does not exist"); "" when present or
  // not looked for. The statistics' fallback warnings quote it.
  std::string probe_absent, sidecar_absent;
  std::vector<LightRecord> lights;  // from the sidecar
  double footprint_at_1m = 0;       // world size of one pixel at depth 1 (sidecar camera); 0: unknown
  CameraView camera;                // from the sidecar; known = false without one
  std::string source;
  std::vector<std::string> notes;   // what the reader found or missed, for --explain

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
};

// Whether pixel i is background (no geometry): the reader's mask, else its rule on the depth;
// false without depth.
inline bool is_background(const SceneData& s, std::size_t i) {
  if (!s.background.empty()) return s.background[i] != 0;
  return !s.depth.empty() && scene::is_background_depth(s.depth[i]);
}

// Whether pixel i's normal has a direction: the reader's mask, else its rule on the stored length.
// Requires a normal plane.
inline bool has_normal(const SceneData& s, std::size_t i) {
  if (!s.normal_valid.empty()) return s.normal_valid[i] != 0;
  const float* v = &s.normal[3 * i];
  return scene::normal_has_direction(std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]));
}

}  // namespace cgtmo::local
