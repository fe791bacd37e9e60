#pragma once
// Display encoding of a request: the check that a display or view is named only when the output is
// display-encoded, and display encoding of a buffer in one call. Both pipelines (pipeline::Applier,
// local::apply_scene_file), the CLI, the Python module and the evaluation go through these.
#include <string>

namespace cgtmo::display {

// Throws UsageError when `display` or `view` is given although the output is not display-encoded
// (`encode_display` false): they would be ignored silently otherwise.
void check_display_choice(bool encode_display, const std::string& display, const std::string& view);

// Display-encodes display-linear RGB(A) in place with the given (or default) config/display/view
// (load_config, DisplayEncoder). The resolved display, view and config origin are returned on request.
void encode_for_display(float* rgb, int width, int height, int channels, const std::string& colorconfig,
                        const std::string& display, const std::string& view, std::string* display_out = nullptr,
                        std::string* view_out = nullptr, std::string* origin = nullptr);

}  // namespace cgtmo::display
