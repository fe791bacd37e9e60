#include "cgtmo/io/exr_luma_chroma.h"

#include <ImathBox.h>
#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <exception>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"
#include "cgtmo/io/input_file.h"

namespace cgtmo::io {

namespace {

// Opens after the checks every image gets (a regular file; declared sizes within what the file
// holds and the memory budget), so OpenEXR allocates nothing a small file could inflate.
std::unique_ptr<Imf::RgbaInputFile> open_rgba(const std::string& path) {
  require_input_file(path);
  check_exr_declared_size(path);
  try {
    return std::make_unique<Imf::RgbaInputFile>(path.c_str());
  } catch (const std::exception& e) {
    throw DataError("'" + path + "': cannot read as OpenEXR: " + first_line(e.what()));
  }
}

Rect rect_of(const Imath::Box2i& b) { return Rect{b.min.x, b.min.y, b.max.x - b.min.x + 1, b.max.y - b.min.y + 1}; }

}  // namespace

bool is_luma_chroma_exr(const std::string& path) {
  // Not a regular file (a FIFO would block the header read): the ordinary reader refuses it.
  if (!input_file_problem(path).empty()) return false;
  ExrDeclaration d;
  try {
    if (!read_exr_declaration(path, &d)) return false;
  } catch (const DataError&) {
    return false;  // the ordinary reader reports a corrupt header
  }
  return !d.parts.empty() && is_luma_chroma_layout(d.parts[0]);  // other subsampling: refused by the checks
}

Part luma_chroma_part(const std::string& path) {
  const auto in = open_rgba(path);
  Part p;
  p.data = rect_of(in->dataWindow());
  p.display = rect_of(in->displayWindow());
  p.width = p.data.width;
  p.height = p.data.height;
  p.names = {"R", "G", "B"};
  if (in->channels() & Imf::WRITE_A) p.names.push_back("A");
  if (p.width <= 0 || p.height <= 0) throw DataError("'" + path + "': empty image");
  return p;
}

std::vector<float> read_luma_chroma(const std::string& path, const Part& part) {
  const auto in = open_rgba(path);
  const Imath::Box2i dw = in->dataWindow();
  const std::size_t w = std::size_t(part.width), h = std::size_t(part.height), k = part.names.size();
  std::vector<float> out(w * h * k);
  // A band of rows at a time: the half RGBA buffer stays small beside the float result.
  const int band = 64;
  Imf::Array2D<Imf::Rgba> rows(band, long(w));
  try {
    for (int y0 = dw.min.y; y0 <= dw.max.y; y0 += band) {
      const int y1 = std::min(dw.max.y, y0 + band - 1);
      in->setFrameBuffer(&rows[0][0] - dw.min.x - std::ptrdiff_t(y0) * std::ptrdiff_t(w), 1, w);
      in->readPixels(y0, y1);
      for (int y = y0; y <= y1; ++y) {
        float* dst = out.data() + std::size_t(y - dw.min.y) * w * k;
        const Imf::Rgba* src = rows[y - y0];
        for (std::size_t x = 0; x < w; ++x) {
          dst[x * k + 0] = float(src[x].r);
          dst[x * k + 1] = float(src[x].g);
          dst[x * k + 2] = float(src[x].b);
          if (k == 4) dst[x * k + 3] = float(src[x].a);
        }
      }
    }
  } catch (const std::exception& e) {
    throw DataError("'" + path + "': corrupt or truncated: " + first_line(e.what()));
  }
  return out;
}

bool luma_chroma_chromaticities(const std::string& path, float xy[8]) {
  const auto in = open_rgba(path);
  if (!Imf::hasChromaticities(in->header())) return false;
  const Imf::Chromaticities& c = Imf::chromaticities(in->header());
  const Imath::V2f v[4] = {c.red, c.green, c.blue, c.white};
  for (int i = 0; i < 4; ++i) {
    xy[2 * i] = v[i].x;
    xy[2 * i + 1] = v[i].y;
  }
  return true;
}

std::vector<std::pair<std::string, std::string>> luma_chroma_string_attributes(const std::string& path) {
  const auto in = open_rgba(path);
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = in->header().begin(); it != in->header().end(); ++it)
    if (const auto* a = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) out.emplace_back(it.name(), a->value());
  return out;
}

}  // namespace cgtmo::io
