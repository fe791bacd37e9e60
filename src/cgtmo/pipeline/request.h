#pragma once
// What every apply request (pipeline::Applier, local::apply_scene_file, and through them the CLI,
// the Python module and the Blender add-on) checks and resolves before any pixel is read, written
// once so that every front end refuses the same requests with the same message.
#include <memory>
#include <string>

#include "cgtmo/display/display.h"

namespace cgtmo::pipeline {

// The exposure range (stops) a request may ask for: 2^64 is far beyond any render's range, and
// larger factors overflow float32 for ordinary radiances.
constexpr int kMaxExposureStops = 64;

// Throws UsageError "exposure must be within [-64, 64] stops" for a non-finite or larger |EV|.
void check_exposure(double ev);

// The OpenColorIO side of a request: the config (which names the input colour space too, with or
// without display encoding) and the display encoder, null without display encoding.
struct ColourSetup {
  display::OCIO::ConstConfigRcPtr config;  // null: no display encoding, no colour space, no config found
  std::unique_ptr<display::DisplayEncoder> encoder;
  std::string config_origin;  // which config the encoder uses (load_config); "" without encoding
};

// Throws UsageError: a display or view without display encoding (display::check_display_choice),
// an unknown colour space, display or view.
ColourSetup setup_colour(bool encode_display, const std::string& colorconfig, const std::string& colorspace,
                         const std::string& display, const std::string& view);

}  // namespace cgtmo::pipeline
