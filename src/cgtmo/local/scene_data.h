#pragma once
// What the CG-TMO pipeline reads from a render: the beauty, the G-buffer planes, the light-group
// passes, the adaptation probe and the sidecar's lights. Plain data; every plane is optional
// except the beauty, and the pipeline says what it did without a missing one (Explain).
#include <limits>
#include <string>
#include <vector>

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
  std::vector<float> normal;    // xyz interleaved, world space as stored (not renormalised), or empty
  std::vector<float> albedo;    // rgb interleaved (diffuse colour), or empty
  std::vector<float> depth;     // planar camera depth, background 1e10, or empty
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

// Depth at or beyond this is background (Blender writes 1e10 where no geometry was hit).
inline constexpr float kBackgroundDepth = 1e9f;

}  // namespace cgtmo::local
