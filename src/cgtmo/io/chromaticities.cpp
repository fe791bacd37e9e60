#include "cgtmo/io/chromaticities.h"

#include <OpenImageIO/imageio.h>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

std::optional<color::Chromaticities> read_chromaticities(const std::string& path) {
  // Through the readers' checks: a FIFO or a device is refused before OIIO opens it.
  const auto in = open_image_input(path);
  const OIIO::ImageSpec& spec = in->spec();
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

}  // namespace cgtmo::io
