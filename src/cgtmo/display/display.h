#pragma once
// Display encoding through OpenColorIO: from the config's scene_linear role to a display/view.
// Operators output display-linear values; the "Standard" view of our configs (and Blender's)
// only applies the display's inverse EOTF, so it is the default view.
#include <OpenColorIO/OpenColorIO.h>

#include <string>

#include "cgtmo/display/profile.h"

namespace cgtmo::display {

namespace OCIO = OCIO_NAMESPACE;

// The config to use: `path` when given, else $OCIO, else the built-in one (sRGB, Rec.1886 and
// Display P3 displays with Standard and Raw views). `origin` says which was taken.
OCIO::ConstConfigRcPtr load_config(const std::string& path, std::string* origin = nullptr);

// The built-in config as OCIO YAML.
const char* builtin_config_yaml();

class DisplayEncoder {
 public:
  // Empty display: the config's default; empty view: "Standard" when the display has it, else
  // the display's default view. Throws UsageError naming the valid choices.
  DisplayEncoder(OCIO::ConstConfigRcPtr config, std::string display, std::string view);
  const std::string& display() const { return display_; }
  const std::string& view() const { return view_; }

  // In place, interleaved float RGB(A), parallel over rows.
  void apply(float* px, int width, int height, int channels) const;

  // What the display encodes (primaries, white, curve) and its ICC profile, when the view's colour
  // space is a matrix and a curve (display/profile.h); else profile().known is false.
  const DisplayProfile& profile() const { return profile_; }

  // The name of the cgtmo operator that the view itself applies ("" when none): a view of one of
  // cgtmo's configs named after an operator, or whose looks are an operator's look ("<op>" or
  // "<op> - <exposure>"). Applying an operator before such a view tone-maps twice.
  std::string view_operator() const { return view_operator_; }

 private:
  DisplayProfile profile_;
  std::string view_operator_;
  OCIO::ConstCPUProcessorRcPtr cpu_;
  std::string display_, view_;
};

}  // namespace cgtmo::display
