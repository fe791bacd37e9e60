#include "cgtmo/io/chromaticities.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_input.h"

namespace cgtmo::io {

std::optional<color::Chromaticities> read_chromaticities(const std::string& path) {
  float v[8];
  if (is_luma_chroma_exr(path)) {  // OpenImageIO cannot open these
    if (!luma_chroma_chromaticities(path, v)) return std::nullopt;
  } else {
    // Through the readers' checks: a FIFO or a device is refused before OIIO opens it.
    const auto in = open_image_input(path);
    const OIIO::ParamValue* p = in->spec().find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
    if (!p) return std::nullopt;
    std::copy_n(static_cast<const float*>(p->data()), 8, v);
  }
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
