#pragma once
// The one scene model: a render in memory. The beauty (RGB or RGBA, interleaved float32), the
// G-buffer planes with the reader's masks, the light-group passes, and what the companion files
// say (the adaptation probe's luminance, the sidecar's lights and camera).
//
// Who fills what:
//   io::read_scene (io/scene_reader.h)  the planes as stored in the file, the masks, light groups
//                                       as RGB; io::Scene adds the file's own record (windows,
//                                       channel names, the companions as read).
//   local::load_scene (local/scene_load.h)  the same Frame, made ready for the scene operators in
//                                       place: radiometric planes in linear Rec.709, the beauty
//                                       sanitised, light groups reduced to luminance, the probe
//                                       and sidecar attached (probe, lights, camera).
//   tests and benchmarks                build one by hand; every plane but the beauty is optional.
// A plane that was not asked for, or that the file lacks, is empty; the pipeline says what it did
// without it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cgtmo::scene {

// One light group's contribution (Blender's Combined_<group> pass).
struct LightGroupPlane {
  std::string name;
  std::vector<float> rgb;        // RGB interleaved, as read; freed once reduced to `luminance`
  std::vector<float> luminance;  // Rec.709 Y per pixel (local::load_scene), what the statistics use
  bool all_zero = false;  // no pixel carries any light of this group (a dark world, a hidden light)
};

// The adaptation probe: a small equirectangular render around the camera (64x32, row 0 straight
// up), kept as luminance.
struct Probe {
  int width = 0, height = 0;
  std::vector<float> luminance;  // width*height, Rec.709 Y
  std::string source;            // file it was read from
};

// One emitter as the sidecar lists it.
struct LightRecord {
  std::string name, type, group;
  double luminance = std::numeric_limits<double>::quiet_NaN();  // emitted, render units; NaN: unknown
};

// The camera as the sidecar gives it, for view-weighted adaptation (local/stats.h). World space, Z up.
struct CameraView {
  bool known = false;
  double forward[3] = {0, 0, -1}, right[3] = {1, 0, 0}, up[3] = {0, 1, 0};  // unit vectors
  double fov_x = 0, fov_y = 0;  // full angles of the frame, radians
  // Azimuth (from +X, counter-clockwise seen from above) of the probe's centre column; NaN: the
  // camera's own heading (how scripts/blender/render_scene.py renders the probe).
  double probe_heading = std::numeric_limits<double>::quiet_NaN();
};

struct Frame {
  int width = 0;
  int height = 0;
  int channels = 3;  // 3 (RGB) or 4 (RGBA): alpha passes through untouched
  std::vector<float> beauty;  // width*height*channels
  std::string source;      // file it was read from
  std::string layer;       // channel prefix used, e.g. "ViewLayer.Combined" ("" for plain R,G,B)

  // G-buffer. Vectors are 3 floats per pixel (x,y,z or r,g,b), scalars 1 per pixel, row-major
  // from the top-left pixel, like the beauty. Position, normal and depth are geometry, never
  // colour-converted or exposed.
  std::vector<float> position;          // world space (Blender: first sample, not anti-aliased)
  std::vector<float> normal;            // world space, renormalised; (0,0,0) where invalid
  std::vector<float> albedo;            // diffuse colour in [0,1] (Blender's DiffCol)
  std::vector<float> depth;             // camera distance; >= kBackgroundDepth on the background
  std::vector<float> emission;          // directly visible emission (Blender's Emit)
  // The reader's masks, or empty: a frame built by hand goes without, and is_background /
  // has_normal derive them by the reader's rules. Whoever changes depth or normal after reading
  // clears the matching mask.
  std::vector<std::uint8_t> background;    // 1 where no geometry was hit (is_background_depth)
  std::vector<std::uint8_t> normal_valid;  // 1 where the normal had a direction (normal_has_direction)
  std::vector<LightGroupPlane> light_groups;

  // From the companion files (local::load_scene).
  Probe probe;                      // empty without one
  bool has_sidecar = false;
  std::vector<LightRecord> lights;  // the sidecar's emitters
  double footprint_at_1m = 0;       // world size of one pixel at depth 1 (sidecar camera); 0: unknown
  CameraView camera;                // known = false without a sidecar
  // Why a companion is absent, naming the file ("'x.json' does not exist"); "" when present or
  // not looked for. The statistics' fallback warnings quote it.
  std::string probe_absent, sidecar_absent;
  std::vector<std::string> notes;   // what the reader found or missed, for --explain

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
  // Pixel i's RGB (alpha, when there is one, follows it).
  const float* rgb_at(std::size_t i) const { return &beauty[i * std::size_t(channels)]; }
};

// The beauty's colour, 3 floats per pixel (alpha dropped): for what takes RGB only (TMQI, a view).
inline std::vector<float> rgb_of(const Frame& f) {
  if (f.channels == 3) return f.beauty;
  std::vector<float> rgb(f.pixel_count() * 3);
  for (std::size_t i = 0; i < f.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = f.rgb_at(i)[c];
  return rgb;
}

// Blender writes 1e10 as the depth of background pixels. Anything at or above 1e9 counts as
// background, so a file whose depth went through a lossy 24-bit codec still masks correctly.
inline constexpr float kBackgroundDepth = 1e9f;
// A stored normal shorter than this has no direction: averaged normals shrink on silhouettes (to
// about 0.2), and below this length the direction is noise.
inline constexpr double kMinNormalLength = 1e-3;

// The rules behind Frame::background and Frame::normal_valid. A non-finite depth is background too.
inline bool is_background_depth(float depth) { return !(std::isfinite(depth) && depth < kBackgroundDepth); }
inline bool normal_has_direction(double length) { return std::isfinite(length) && length > kMinNormalLength; }

// Whether pixel i is background (no geometry): the reader's mask, else its rule on the depth;
// false without depth.
inline bool is_background(const Frame& f, std::size_t i) {
  if (!f.background.empty()) return f.background[i] != 0;
  return !f.depth.empty() && is_background_depth(f.depth[i]);
}

// Whether pixel i's normal has a direction: the reader's mask, else its rule on the stored length.
// Requires a normal plane.
inline bool has_normal(const Frame& f, std::size_t i) {
  if (!f.normal_valid.empty()) return f.normal_valid[i] != 0;
  const float* v = &f.normal[3 * i];
  return normal_has_direction(std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]));
}

}  // namespace cgtmo::scene
