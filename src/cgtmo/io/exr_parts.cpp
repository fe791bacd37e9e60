#include "cgtmo/io/exr_parts.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

std::vector<Part> read_parts(const std::string& path) {
  auto in = open_image_input(path);
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

std::vector<std::vector<float>> read_part_channel_sets(const std::string& path, const Part& part,
                                                       const std::vector<std::vector<std::string>>& sets) {
  std::vector<std::vector<int>> idx(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (const auto& n : sets[i]) {
      const auto it = std::find(part.names.begin(), part.names.end(), n);
      if (it == part.names.end()) throw DataError("'" + path + "': no channel '" + n + "'");
      idx[i].push_back(int(it - part.names.begin()));
    }
  const int w = part.width, h = part.height;
  const std::size_t npx = std::size_t(w) * std::size_t(h);
  std::vector<std::vector<float>> out(sets.size());
  for (std::size_t i = 0; i < sets.size(); ++i) out[i].resize(npx * sets[i].size());
  // 32 scanlines at a time (a multiple of every EXR compression's chunk height), each set's runs of
  // contiguous channels read straight into place: OpenEXR keeps a block's decompressed chunks
  // between the reads, so each is decompressed once for all the sets. (Blocks on several threads,
  // each with its own reader, were no faster and held more memory: docs/cgtmo.md section 9.)
  auto in = open_image_input(path);
  if (!in->seek_subimage(part.index, 0))
    throw DataError("'" + path + "': cannot seek to part " + std::to_string(part.index) + ": " + first_line(in->geterror()));
  const int y_origin = in->spec().y, z = in->spec().z;
  // A tiled file is read whole (tiles hold every channel too, but come in no order of rows).
  const int block = in->spec().tile_width > 0 ? h : 32;
  for (int y0 = 0; y0 < h; y0 += block) {
    const int y1 = std::min(h, y0 + block);
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const std::size_t k = idx[i].size();
      float* dst = out[i].data() + std::size_t(y0) * std::size_t(w) * k;
      const OIIO::stride_t xstride = OIIO::stride_t(k * sizeof(float)), ystride = xstride * w;
      for (std::size_t a = 0; a < k;) {
        std::size_t e = a + 1;
        while (e < k && idx[i][e] == idx[i][e - 1] + 1) ++e;
        const bool ok = block == h ? in->read_image(part.index, 0, idx[i][a], idx[i][e - 1] + 1, OIIO::TypeDesc::FLOAT, dst + a, xstride)
                                   : in->read_scanlines(part.index, 0, y_origin + y0, y_origin + y1, z, idx[i][a], idx[i][e - 1] + 1,
                                                        OIIO::TypeDesc::FLOAT, dst + a, xstride, ystride);
        if (!ok)
          throw DataError("'" + path + "': corrupt or truncated: " + first_line(in->geterror()));
        a = e;
      }
    }
  }
  return out;
}

}  // namespace cgtmo::io
