#include "cgtmo/io/exr_parts.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>

#include "cgtmo/errors.h"

namespace cgtmo::io {

namespace {

std::string first_line(std::string s) {
  s = s.substr(0, s.find('\n'));
  return s.empty() ? "unknown error" : s;
}

std::unique_ptr<OIIO::ImageInput> open_input(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw DataError("'" + path + "': no such file");
  if (std::filesystem::is_directory(path, ec)) throw DataError("'" + path + "': is a folder, not an image");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw DataError("'" + path + "': cannot read as an image: " + first_line(OIIO::geterror()));
  return in;
}

}  // namespace

std::vector<Part> read_parts(const std::string& path) {
  auto in = open_input(path);
  std::vector<Part> parts;
  for (int i = 0; in->seek_subimage(i, 0); ++i) {
    const OIIO::ImageSpec& s = in->spec();
    Part p;
    p.index = i;
    p.width = s.width;
    p.height = s.height;
    p.name = s.get_string_attribute("name");
    p.names = s.channelnames;
    if (p.width <= 0 || p.height <= 0) throw DataError("'" + path + "': part " + std::to_string(i) + " is empty");
    parts.push_back(std::move(p));
  }
  if (parts.empty()) throw DataError("'" + path + "': no image in the file");
  return parts;
}

std::vector<float> read_part_channels(const std::string& path, const Part& part, const std::vector<std::string>& names) {
  std::vector<int> idx;
  for (const auto& n : names) {
    const auto it = std::find(part.names.begin(), part.names.end(), n);
    if (it == part.names.end()) throw DataError("'" + path + "': no channel '" + n + "'");
    idx.push_back(int(it - part.names.begin()));
  }
  auto in = open_input(path);
  if (!in->seek_subimage(part.index, 0))
    throw DataError("'" + path + "': cannot seek to part " + std::to_string(part.index) + ": " + first_line(in->geterror()));
  const std::size_t npx = std::size_t(part.width) * std::size_t(part.height);
  const int k = int(names.size());
  std::vector<float> out(npx * std::size_t(k));
  // Contiguous runs of wanted channels are read straight into place (strided).
  std::size_t i = 0;
  while (i < idx.size()) {
    std::size_t j = i + 1;
    while (j < idx.size() && idx[j] == idx[j - 1] + 1) ++j;
    const OIIO::stride_t xstride = OIIO::stride_t(k * sizeof(float));
    if (!in->read_image(part.index, 0, idx[i], idx[j - 1] + 1, OIIO::TypeDesc::FLOAT, out.data() + i, xstride))
      throw DataError("'" + path + "': corrupt or truncated: " + first_line(in->geterror()));
    i = j;
  }
  return out;
}

}  // namespace cgtmo::io
