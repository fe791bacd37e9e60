#pragma once
// Display encoding through OpenColorIO: from the config's scene_linear role to a display/view.
// Operators output display-linear values; the "Standard" view of our configs (and Blender's)
// only applies the display's inverse EOTF, so it is the default view.
#include <OpenColorIO/OpenColorIO.h>

#include <string>

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

 private:
  OCIO::ConstCPUProcessorRcPtr cpu_;
  std::string display_, view_;
};

}  // namespace cgtmo::display
