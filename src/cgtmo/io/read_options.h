#pragma once
// How a render's file is read, beyond which passes: the pixel window and, for a multi-view
// (stereo) OpenEXR, the view. Shared by the scene reader, the beauty-only reader and the CLI.
#include <string>
#include <vector>

#include "cgtmo/scene/passes.h"

namespace cgtmo::io {

// Which rectangle of the image plane becomes the frame.
//   Display: the beauty part's display window (the frame as the camera framed it). Pixels of a
//            pass outside its part's data window read as zero, depth as background (1e10).
//   Data:    the beauty part's data window (its stored pixels: overscan kept, auto-crop kept
//            cropped); other parts are placed on it the same way.
enum class Window { Display, Data };

struct ReadOptions {
  Window window = Window::Display;
  std::string view;  // multi-view OpenEXR: the view to read; "" = the file's default (first) view
  std::vector<scene::PassOverride> passes;  // --pass role=LAYER, applied after the automatic mapping
};

const char* window_name(Window w);  // "display", "data"
// Parses "display" or "data". Throws UsageError naming the choices.
Window parse_window(const std::string& text);

}  // namespace cgtmo::io
