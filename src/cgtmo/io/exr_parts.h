#pragma once
// The parts (OIIO subimages) of a file with their sizes and channel names, and reading named
// channels from one part. image_io.h covers single-part files (Blender's multilayer EXR is one
// part); the scene reader uses these to find passes stored in other parts (Nuke-style
// multi-part EXR) and to refuse parts whose size differs from the beauty's.
#include <string>
#include <vector>

namespace cgtmo::io {

struct Part {
  int index = 0;
  int width = 0, height = 0;
  std::string name;                // the part's name attribute, "" when it has none
  std::vector<std::string> names;  // channel names in file order
};

// Every part of the file. Throws DataError (missing, unreadable, not an image, empty part).
std::vector<Part> read_parts(const std::string& path);

// The named channels of one part as float32, names.size() values per pixel (interleaved).
// Only the runs of channels asked for are decoded. Throws DataError (unknown name, truncated).
std::vector<float> read_part_channels(const std::string& path, const Part& part, const std::vector<std::string>& names);

}  // namespace cgtmo::io
