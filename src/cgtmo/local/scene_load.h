#pragma once
// Reads a render for the scene operators through the project's scene reader (io/scene_reader.h):
// the beauty (sanitised by scene/sanitize.h), depth, the G-buffer and light-group passes when
// asked for, the NAME.probe.exr probe and the NAME.json sidecar. The result is the reader's own
// scene::Frame, completed in place (scene/frame.h says which part each stage fills): nothing is
// copied from one model to another. Missing optional planes and companions are noted
// (scene::Frame::notes), not errors.
// The radiometric planes (beauty, light groups, albedo, emission, probe) are converted to linear
// Rec.709 first (color/input_space.h), each file by its own chromaticities attribute unless a
// colour space is named; position, normal and depth are not colours and stay as read.
#include <OpenColorIO/OpenColorIO.h>

#include <string>

#include "cgtmo/scene/frame.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/read_options.h"
#include "cgtmo/scene/sanitize.h"

namespace cgtmo::local {

struct LoadRequest {
  std::string path;
  std::string layer;         // beauty layer (io::find_beauty); "" = automatic
  std::string needed_by = "cgtmo";
  bool gbuffer = true;       // position, normal, albedo
  bool light_groups = true;
  bool probe = true;
  bool sidecar = true;
  std::string probe_path;    // "" = NAME.probe.exr beside the render
  std::string sidecar_path;  // "" = NAME.json beside the render
  // The input colour space: `colorspace` names one of `config` (checked by the caller), "" =
  // each file's chromaticities attribute, else the scene_linear role of `config` (null: no
  // config), else linear Rec.709.
  std::string colorspace;
  OCIO_NAMESPACE::ConstConfigRcPtr config;
  io::ReadOptions read;      // window (display or data), EXR view
  io::FrameWork work;        // what the operator holds beside the planes (io/input_file.h)
  // An explicit probe_path or sidecar_path that is not there: a warning (companion_warnings)
  // rather than a DataError.
  bool explicit_companions_optional = false;
};

struct LoadResult {
  scene::Frame scene;
  scene::SanitizeReport beauty_report;  // the non-finite policy applied to the beauty
  std::string input_space;              // the render's colour space as resolved
  std::vector<std::string> warnings;    // a named colour space disagreeing with an attribute
  // A line for a sidecar that was asked for but not used (absent, or foreign) when the frame has
  // light groups, naming the file and what is used instead. (Without light groups, and for the
  // probe, the statistics' fallback warnings name it: scene::Frame::probe_absent, sidecar_absent.)
  std::vector<std::string> companion_warnings;
};

LoadResult load_scene(const LoadRequest& request);

// Exposure by `scale` (2^EV) of everything radiometric in the scene: the beauty's colour (clamped to the
// sanitiser's maximum), the light-group passes, the sidecar's emitted luminances and the probe,
// so the scene statistics (Lw_max, Lw_a) scale with the exposure like the beauty does.
// Position, normal, albedo and depth are not light and stay.
void expose_scene(scene::Frame& scene, double scale);

}  // namespace cgtmo::local
