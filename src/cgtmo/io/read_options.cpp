#include "cgtmo/io/read_options.h"

#include "cgtmo/errors.h"

namespace cgtmo::io {

const char* window_name(Window w) { return w == Window::Data ? "data" : "display"; }

Window parse_window(const std::string& text) {
  if (text == "display") return Window::Display;
  if (text == "data") return Window::Data;
  throw UsageError("--window '" + text + "': use display or data");
}

}  // namespace cgtmo::io
