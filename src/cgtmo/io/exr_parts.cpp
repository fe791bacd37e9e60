#include "cgtmo/io/exr_parts.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

std::vector<Part> read_parts(const std::string& path) {
  if (is_luma_chroma_exr(path)) return {luma_chroma_part(path)};
  auto in = open_image_input(path);
  std::vector<Part> parts;
  for (int i = 0; in->seek_subimage(i, 0); ++i) {
    const OIIO::ImageSpec& s = in->spec();
    Part p;
    p.index = i;
    p.width = s.width;
    p.height = s.height;
    p.data = Rect{s.x, s.y, s.width, s.height};
    p.display = s.full_width > 0 && s.full_height > 0 ? Rect{s.full_x, s.full_y, s.full_width, s.full_height} : p.data;
    p.name = s.get_string_attribute("name");
    p.names = s.channelnames;
    p.view = s.get_string_attribute("view");
    if (const OIIO::ParamValue* mv = s.find_attribute("multiView"); mv && mv->type().basetype == OIIO::TypeDesc::STRING)
      for (int k = 0; k < int(mv->type().numelements()) * mv->nvalues(); ++k) p.multi_view.emplace_back(mv->get<OIIO::ustring>(k).string());
    if (p.width <= 0 || p.height <= 0) throw DataError("'" + path + "': part " + std::to_string(i) + " is empty");
    parts.push_back(std::move(p));
  }
  if (parts.empty()) throw DataError("'" + path + "': no image in the file");
  return parts;
}

std::vector<std::string> views_of(const std::vector<Part>& parts) {
  std::vector<std::string> views;
  auto add = [&views](const std::string& v) {
    if (!v.empty() && std::find(views.begin(), views.end(), v) == views.end()) views.push_back(v);
  };
  for (const auto& p : parts)
    for (const auto& v : p.multi_view) add(v);
  for (const auto& p : parts) add(p.view);
  return views;
}

namespace {
// The start of the view component of `name`, or npos when it has none.
std::size_t view_component(const std::string& name, const std::vector<std::string>& multi_view) {
  const std::size_t last = name.rfind('.');
  if (last == std::string::npos) return std::string::npos;
  const std::size_t before = name.rfind('.', last == 0 ? 0 : last - 1);
  const std::size_t start = before == std::string::npos || before >= last ? 0 : before + 1;
  const std::string v = name.substr(start, last - start);
  return std::find(multi_view.begin(), multi_view.end(), v) != multi_view.end() ? start : std::string::npos;
}
}  // namespace

std::string view_of_channel(const std::string& name, const std::vector<std::string>& multi_view) {
  if (multi_view.empty()) return "";
  const std::size_t at = view_component(name, multi_view);
  return at == std::string::npos ? multi_view[0] : name.substr(at, name.rfind('.') - at);
}

std::string without_view(const std::string& name, const std::vector<std::string>& multi_view) {
  const std::size_t at = view_component(name, multi_view);
  return at == std::string::npos ? name : name.substr(0, at) + name.substr(name.rfind('.') + 1);
}

std::string rect_text(const Rect& r) {
  return std::to_string(r.width) + "x" + std::to_string(r.height) + " at (" + std::to_string(r.x) + "," + std::to_string(r.y) + ")";
}

void place(const float* src, const Rect& from, float* dst, const Rect& to, int k) {
  const long x0 = std::max<long>(from.x, to.x), x1 = std::min<long>(long(from.x) + from.width, long(to.x) + to.width);
  const long y0 = std::max<long>(from.y, to.y), y1 = std::min<long>(long(from.y) + from.height, long(to.y) + to.height);
  if (x0 >= x1 || y0 >= y1) return;
  const std::size_t run = std::size_t(x1 - x0) * std::size_t(k);
  for (long y = y0; y < y1; ++y) {
    const float* s = src + (std::size_t(y - from.y) * std::size_t(from.width) + std::size_t(x0 - from.x)) * std::size_t(k);
    float* d = dst + (std::size_t(y - to.y) * std::size_t(to.width) + std::size_t(x0 - to.x)) * std::size_t(k);
    std::copy(s, s + run, d);
  }
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
  if (is_luma_chroma_exr(path)) {  // R, G, B (A) reconstructed by OpenEXR, then picked per set
    const std::vector<float> all = read_luma_chroma(path, part);
    const std::size_t k = part.names.size();
    for (std::size_t i = 0; i < sets.size(); ++i)
      for (std::size_t px = 0; px < npx; ++px)
        for (std::size_t j = 0; j < idx[i].size(); ++j) out[i][px * idx[i].size() + j] = all[px * k + std::size_t(idx[i][j])];
    return out;
  }
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
