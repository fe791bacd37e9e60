#pragma once
// Opening an image through OpenImageIO, for the readers of io/ (image_io.cpp, exr_parts.cpp).
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

#include "cgtmo/io/input_file.h"

namespace cgtmo::io {

// Opens `path` for reading after the checks of input_file.h (a regular file; not deep; declared
// size within the memory budget and, for OpenEXR, within what the file can hold). Never lets
// OpenImageIO probe its formats. Throws DataError naming the file.
std::unique_ptr<OIIO::ImageInput> open_image_input(const std::string& path,
                                                   ReaderBy by = ReaderBy::ContentThenExtension);

// The first line of a library's error text ("unknown error" when empty): messages stay one line.
std::string first_line(std::string s);

}  // namespace cgtmo::io
