#pragma once
// The OpenEXR `chromaticities` header attribute (xy of R, G, B and white; OIIO reads it as
// float[8]), which says which RGB primaries a file's pixels are in.
#include <optional>
#include <string>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/input_space.h"

namespace cgtmo::io {

// From the first part's header; nullopt when the file has none, or one that is not 8 floats.
// Throws DataError naming the file when it cannot be opened or its attribute is degenerate
// (collinear primaries, a white with y <= 0, non-finite values).
std::optional<color::Chromaticities> read_chromaticities(const std::string& path);

// The attribute, and whether the pixels are display-referred (stored as integers: an 8- or 16-bit
// PNG, JPEG, TIFF...; EXR, float TIFF and HDR are light). One open of the file.
color::FileColour read_file_colour(const std::string& path);

}  // namespace cgtmo::io
