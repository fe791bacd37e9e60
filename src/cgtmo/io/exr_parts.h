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

// Sets of named channels of one part as float32, set i with sets[i].size() values per pixel
// (interleaved; an empty set gives an empty buffer), all decoded in one pass over the file: a
// compressed chunk of scanlines holds every channel, so reading one pass after another decompressed
// the whole file once per pass. Throws DataError (unknown name, truncated or corrupt data).
std::vector<std::vector<float>> read_part_channel_sets(const std::string& path, const Part& part,
                                                       const std::vector<std::vector<std::string>>& sets);

}  // namespace cgtmo::io
