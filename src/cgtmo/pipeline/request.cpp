#include "cgtmo/pipeline/request.h"

#include <cmath>

#include "cgtmo/color/input_space.h"
#include "cgtmo/display/encode.h"
#include "cgtmo/errors.h"

namespace cgtmo::pipeline {

void check_exposure(double ev) {
  if (!std::isfinite(ev) || std::abs(ev) > kMaxExposureStops) {
    const std::string stops = std::to_string(kMaxExposureStops);
    throw UsageError("exposure must be within [-" + stops + ", " + stops + "] stops");
  }
}

ColourSetup setup_colour(bool encode_display, const std::string& colorconfig, const std::string& colorspace,
                         const std::string& display, const std::string& view) {
  display::check_display_choice(encode_display, display, view);
  ColourSetup s;
  std::string origin;
  s.config = encode_display ? display::load_config(colorconfig, &origin) : color::config_for_input(colorconfig, colorspace, &origin);
  if (!colorspace.empty()) color::check_colorspace_name(s.config, colorspace, origin);
  if (encode_display) {
    s.encoder = std::make_unique<display::DisplayEncoder>(s.config, display, view);
    s.config_origin = origin;
  }
  return s;
}

}  // namespace cgtmo::pipeline
