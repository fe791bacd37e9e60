#pragma once
// OpenEXR files in luminance/chroma form (channels Y, RY, BY, the chroma subsampled 2x2, as
// OpenEXR's RgbaOutputFile writes with WRITE_YC or WRITE_YCA): OpenImageIO refuses subsampled
// channels, so these are read through OpenEXR's RGBA interface (Imf::RgbaInputFile), which
// reconstructs full-resolution R, G, B (and A) from them. The scene reader and the header readers
// present such a file as one part with channels R, G, B (A).
#include <string>
#include <utility>
#include <vector>

#include "cgtmo/io/exr_parts.h"

namespace cgtmo::io {

// True when `path` is an OpenEXR file whose first part has the luminance/chroma layout
// (io::is_luma_chroma_layout). Reads the header bytes only (input_file.h), and only of a regular
// file; false for anything else.
bool is_luma_chroma_exr(const std::string& path);

// The file as one part: its windows, and R, G, B (and A when stored).
Part luma_chroma_part(const std::string& path);

// Its pixels over the data window, RGB(A) interleaved as float32 (part.names.size() per pixel).
// Throws DataError (corrupt or truncated data).
std::vector<float> read_luma_chroma(const std::string& path, const Part& part);

// What the other readers take from the header through OpenImageIO, which cannot open these files:
// the chromaticities attribute (false when absent; red, green, blue, white as x, y pairs), and the
// string attributes (owner, capDate, ...) for an output to carry on.
bool luma_chroma_chromaticities(const std::string& path, float xy[8]);
std::vector<std::pair<std::string, std::string>> luma_chroma_string_attributes(const std::string& path);

}  // namespace cgtmo::io
