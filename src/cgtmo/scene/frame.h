#pragma once
// A render in memory: the beauty (RGB or RGBA, interleaved float32) and where it came from.
// G-buffer planes join this structure with the scene reader.
#include <cstddef>
#include <string>
#include <vector>

namespace cgtmo::scene {

struct Frame {
  int width = 0;
  int height = 0;
  int channels = 3;  // 3 (RGB) or 4 (RGBA): alpha passes through untouched
  std::vector<float> beauty;
  std::string source;      // file it was read from
  std::string layer;       // channel prefix used, e.g. "ViewLayer.Combined" ("" for plain R,G,B)

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
};

}  // namespace cgtmo::scene
