#include "cgtmo/io/chromaticities.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

namespace {

// The attribute's 8 floats as chromaticities; DataError naming the file when they are degenerate.
color::Chromaticities checked_chromaticities(const float* v, const std::string& path) {
  const color::Chromaticities c =
      color::published_from_float32({{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
  try {
    color::rgb_to_xyz(c);  // degenerate primaries or white: an error naming the file, now
  } catch (const DataError& e) {
    throw DataError(path + ": unusable chromaticities attribute (" + color::describe(c) + "): " + e.what());
  }
  return c;
}

}  // namespace

std::optional<color::Chromaticities> read_chromaticities(const std::string& path) { return read_file_colour(path).chromaticities; }

color::FileColour read_file_colour(const std::string& path) {
  color::FileColour f;
  float v[8];
  if (is_luma_chroma_exr(path)) {  // OpenImageIO cannot open these; they hold half floats: light
    if (luma_chroma_chromaticities(path, v)) f.chromaticities = checked_chromaticities(v, path);
    return f;
  }
  // Through the readers' checks: a FIFO or a device is refused before OIIO opens it.
  const auto in = open_image_input(path);
  const OIIO::ImageSpec& spec = in->spec();
  if (const OIIO::ParamValue* p = spec.find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8))) {
    std::copy_n(static_cast<const float*>(p->data()), 8, v);
    f.chromaticities = checked_chromaticities(v, path);
  }
  const OIIO::TypeDesc t = spec.format;
  if (!t.is_floating_point()) {
    std::string format = in->format_name();
    for (char& ch : format) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    f.display_referred = (t.size() == 1 ? "an 8-bit " : t.size() == 2 ? "a 16-bit " : "an integer ") + format;
  }
  return f;
}

}  // namespace cgtmo::io
