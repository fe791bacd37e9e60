#include "cgtmo/display/encode.h"

#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"

namespace cgtmo::display {

void check_display_choice(bool encode_display, const std::string& display, const std::string& view) {
  if (!encode_display && (!display.empty() || !view.empty()))
    throw UsageError("a display or view cannot be combined with linear (unencoded) output");
}

void encode_for_display(float* rgb, int width, int height, int channels, const std::string& colorconfig,
                        const std::string& display, const std::string& view, std::string* display_out,
                        std::string* view_out, std::string* origin) {
  const DisplayEncoder encoder(load_config(colorconfig, origin), display, view);
  encoder.apply(rgb, width, height, channels);
  if (display_out) *display_out = encoder.display();
  if (view_out) *view_out = encoder.view();
}

}  // namespace cgtmo::display
