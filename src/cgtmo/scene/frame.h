#pragma once
// A render in memory: the beauty (RGB or RGBA, interleaved float32), the G-buffer planes the
// scene reader filled in (io/scene_reader.h), and where it came from. A plane that was not asked
// for, or that the file lacks, is empty.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cgtmo::scene {

// One light group's contribution (Blender's Combined_<group> pass), RGB interleaved.
struct LightGroupPlane {
  std::string name;
  std::vector<float> rgb;
  bool all_zero = false;  // no pixel carries any light of this group (a dark world, a hidden light)
};

struct Frame {
  int width = 0;
  int height = 0;
  int channels = 3;  // 3 (RGB) or 4 (RGBA): alpha passes through untouched
  std::vector<float> beauty;
  std::string source;      // file it was read from
  std::string layer;       // channel prefix used, e.g. "ViewLayer.Combined" ("" for plain R,G,B)

  // G-buffer. Vectors are 3 floats per pixel (x,y,z or r,g,b), scalars 1 per pixel, row-major
  // from the top-left pixel, like the beauty.
  std::vector<float> position;          // world space (Blender: first sample, not anti-aliased)
  std::vector<float> normal;            // world space, renormalised; (0,0,0) where invalid
  std::vector<std::uint8_t> normal_valid;  // 1 where the normal had a direction (normal_has_direction)
  std::vector<float> albedo;            // diffuse colour in [0,1] (Blender's DiffCol)
  std::vector<float> depth;             // camera distance; >= kBackgroundDepth on the background
  std::vector<std::uint8_t> background;    // 1 where no geometry was hit (is_background_depth)
  std::vector<float> emission;          // directly visible emission (Blender's Emit)
  std::vector<LightGroupPlane> light_groups;

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
};

// Blender writes 1e10 as the depth of background pixels. Anything at or above 1e9 counts as
// background, so a file whose depth went through a lossy 24-bit codec still masks correctly.
inline constexpr float kBackgroundDepth = 1e9f;
// A stored normal shorter than this has no direction: averaged normals shrink on silhouettes (to
// about 0.2), and below this length the direction is noise.
inline constexpr double kMinNormalLength = 1e-3;

// The rules behind Frame::background and Frame::normal_valid, for whoever holds the planes
// without the reader's masks. A non-finite depth is background too.
inline bool is_background_depth(float depth) { return !(std::isfinite(depth) && depth < kBackgroundDepth); }
inline bool normal_has_direction(double length) { return std::isfinite(length) && length > kMinNormalLength; }

}  // namespace cgtmo::scene
