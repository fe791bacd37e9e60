#pragma once
// The parts (OIIO subimages) of a file with their sizes and channel names, and reading named
// channels from one part. The scene reader uses these to find passes stored in other parts
// (Nuke-style multi-part EXR) and to place each part's data window on the frame's window.
#include <string>
#include <vector>

namespace cgtmo::io {

// A rectangle of the image plane in pixels (OpenEXR's windows; y grows downwards).
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const Rect& o) const { return x == o.x && y == o.y && width == o.width && height == o.height; }
  bool operator!=(const Rect& o) const { return !(*this == o); }
};
std::string rect_text(const Rect& r);  // "1920x1080 at (0,0)"

struct Part {
  int index = 0;
  int width = 0, height = 0;       // of the data window (the pixels stored)
  Rect data;                       // the data window
  Rect display;                    // the display window (formats without one: the data window)
  std::string name;                // the part's name attribute, "" when it has none
  std::vector<std::string> names;  // channel names in file order
  std::string view;                // the part's view attribute (multi-part stereo), "" when none
  std::vector<std::string> multi_view;  // the multiView attribute (views of one part's channels)
};

// The views of a multi-view OpenEXR, the default (first) one first: the multiView attribute's,
// then the parts' view attributes. Empty for a file without views.
std::vector<std::string> views_of(const std::vector<Part>& parts);

// The view a channel of a part with a multiView attribute belongs to, by OpenEXR's convention:
// a name of one component ("R") belongs to the default view; otherwise the component before the
// last names the view when it is one of them ("right.R", "beauty.right.R"), else the default.
std::string view_of_channel(const std::string& name, const std::vector<std::string>& multi_view);
// The name without its view component ("beauty.right.R" -> "beauty.R").
std::string without_view(const std::string& name, const std::vector<std::string>& multi_view);

// Every part of the file (a luminance/chroma OpenEXR: one part with R, G, B (A), see
// exr_luma_chroma.h). Throws DataError (missing, unreadable, not an image, empty part).
std::vector<Part> read_parts(const std::string& path);

// Copies `src` (k values per pixel over `from`) into `dst` (k values per pixel over `to`) where the
// two rectangles overlap; the rest of `dst` is left as it is.
void place(const float* src, const Rect& from, float* dst, const Rect& to, int k);

// Sets of named channels of one part as float32, set i with sets[i].size() values per pixel
// (interleaved; an empty set gives an empty buffer), all decoded in one pass over the file: a
// compressed chunk of scanlines holds every channel, so reading one pass after another decompressed
// the whole file once per pass. Throws DataError (unknown name, truncated or corrupt data).
std::vector<std::vector<float>> read_part_channel_sets(const std::string& path, const Part& part,
                                                       const std::vector<std::vector<std::string>>& sets);

}  // namespace cgtmo::io
