#include "cgtmo/io/chromaticities.h"

#include <OpenImageIO/imageio.h>

#include <cctype>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

namespace {

std::optional<color::Chromaticities> chromaticities_of(const OIIO::ImageSpec& spec, const std::string& path) {
  const OIIO::ParamValue* p = spec.find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
  if (!p) return std::nullopt;
  const float* v = static_cast<const float*>(p->data());
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
  // Through the readers' checks: a FIFO or a device is refused before OIIO opens it.
  const auto in = open_image_input(path);
  const OIIO::ImageSpec& spec = in->spec();
  color::FileColour f;
  f.chromaticities = chromaticities_of(spec, path);
  const OIIO::TypeDesc t = spec.format;
  if (!t.is_floating_point()) {
    std::string format = in->format_name();
    for (char& ch : format) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    f.display_referred = (t.size() == 1 ? "an 8-bit " : t.size() == 2 ? "a 16-bit " : "an integer ") + format;
  }
  return f;
}

}  // namespace cgtmo::io
