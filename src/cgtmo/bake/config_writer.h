#pragma once
// The OCIO config: the built-in config's display encodings (one definition, display/display.h),
// plus working spaces, the Log2 Shaper space, one view per baked operator on every display and
// the looks (see docs/ocio.md for how they appear in Blender, oiiotool, Nuke and Resolve).
#include <OpenColorIO/OpenColorIO.h>

#include <string>
#include <vector>

#include "cgtmo/bake/lut.h"
#include "cgtmo/color/matrix.h"

namespace cgtmo::bake {

namespace OCIO = OCIO_NAMESPACE;

struct ConfigView {
  std::string name;         // the operator's name: the view and the look share it
  std::string description;  // operator summary and the baked parameters
  const BakedLut* lut = nullptr;
  std::string lut_file;     // file name, found through the search path
};

// Exposure looks, in stops, offered over the Standard view and over every operator view.
inline constexpr int kExposureStops[] = {-2, -1, 1, 2};
std::string exposure_look_name(const std::string& view, int stops);  // "Standard - +1 stop"

// Builds the config. `search_path`: where the LUT files are (relative to the config's folder, or
// absolute). Views list on every display as: Standard, the operators in registry order, Raw.
OCIO::ConfigRcPtr build_config(const std::vector<ConfigView>& views, const std::string& search_path,
                               const std::string& description);

// Adds one more operator view and look to an existing config (cgtmo bake --scene).
void add_view(OCIO::ConfigRcPtr& config, const ConfigView& view);

// The config as text, with `header` lines as YAML comments on top.
std::string config_text(const OCIO::ConstConfigRcPtr& config, const std::string& header);

}  // namespace cgtmo::bake
