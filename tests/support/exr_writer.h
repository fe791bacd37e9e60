#pragma once
// Writes small synthetic EXR files for the reader tests (single- or multi-part, any channel
// names), and temporary folders that clean up after themselves.
#include <filesystem>
#include <string>
#include <vector>

namespace cgtmo::test {

struct PartSpec {
  int width = 0, height = 0;
  std::vector<std::string> names;
  std::vector<float> pixels;  // names.size() values per pixel; filled by fill() when empty
  std::string part_name;
  int x = 0, y = 0;  // the data window's origin (width x height from there)
  // The display window; full_width 0: the first part's data window. OpenEXR wants every part of
  // a file to have the same display window, so write_exr takes the first part's for all.
  int full_x = 0, full_y = 0, full_width = 0, full_height = 0;
};

// Writes the parts (one part: a plain EXR). Pixels default to value(channel, pixel index).
void write_exr(const std::string& path, std::vector<PartSpec> parts);

// A fresh folder under the system temp folder, removed by the destructor.
struct TempDir {
  std::filesystem::path path;
  TempDir();
  ~TempDir();
  std::string file(const std::string& name) const { return (path / name).string(); }
};

void write_text(const std::string& path, const std::string& text);

}  // namespace cgtmo::test
