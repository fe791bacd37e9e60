#pragma once
// Reads a render with its G-buffer, adaptation probe and sidecar into a scene::Frame.
//
//   io::SceneRequest req;
//   req.required = scene::Pass::Beauty | scene::PassSet::gbuffer();
//   req.needed_by = "cgtmo";
//   io::Scene s = io::read_scene("tests/scenes/cornell/cornell.exr", req);
//
// The frame covers the window that SceneRequest::read chooses (io/read_options.h): by default the
// beauty part's display window. Every pass is placed on it by its part's data window, so overscan,
// auto-cropped and negative-origin data windows, and parts of different sizes (a depth part
// smaller than the beauty), all read; outside a part's data window colour passes read 0 and depth
// reads 1e10 (background).
// A multi-view (stereo) OpenEXR is read as the view SceneRequest::read.view names (default: the
// file's first): the view's channels, named without their view component; a view the file lacks
// is a DataError listing its views.
// Channel names are mapped by scene/passes.h (Blender's and generic spellings). Only the channels
// of the requested passes are decoded. After reading:
//   - depth >= 1e9 (Blender writes 1e10) or non-finite marks a background pixel;
//   - normals are renormalised (Blender averages them over samples); a zero-length or
//     non-finite one becomes (0,0,0) with normal_valid = 0;
//   - a light group whose pass is zero everywhere is flagged and reported in `warnings`.
// The beauty is returned as stored: the non-finite policy (scene/sanitize.h) is the caller's.
//
// Companion files, found by convention beside NAME.exr unless given explicitly:
//   NAME.json        the sidecar (scene/sidecar.h); its camera resolution must match the frame;
//                    a JSON object of another kind (scene::is_foreign_json) is ignored with a
//                    warning; anything else that is not a sidecar is a DataError
//   NAME.probe.exr   the 64x32 equirectangular probe (or the file the sidecar's probe names);
//                    it must be twice as wide as high, and match the sidecar's probe record.
#include <optional>
#include <string>
#include <vector>

#include "cgtmo/io/exr_parts.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/read_options.h"
#include "cgtmo/scene/frame.h"
#include "cgtmo/scene/passes.h"
#include "cgtmo/scene/sidecar.h"

namespace cgtmo::io {

enum class Companion {
  Auto,     // use it when found beside the EXR (or at the explicit path), else go without
  Require,  // a DataError when it is not there
  Skip,     // do not look
  Prefer,   // as Auto, and an explicit path that is not there is a warning, not an error
};

struct SceneRequest {
  scene::PassSet required = scene::Pass::Beauty;  // a missing one is a DataError
  scene::PassSet optional;                         // read when the file has them
  std::string layer;                               // beauty layer (see io::find_beauty)
  std::string needed_by = "cgtmo";                 // operator or command, named in errors
  Companion probe = Companion::Auto;
  std::string probe_path;                          // explicit path ("" = by convention)
  scene::PassSet probe_passes = scene::Pass::Beauty;
  Companion sidecar = Companion::Auto;
  std::string sidecar_path;                        // explicit path ("" = by convention)
  ReadOptions read;                                // window (display or data), view
  // What the caller holds per pixel of the frame beside the planes read: the frame is refused
  // unless both fit the memory budget (input_file.h, check_frame_size).
  FrameWork work;
};

// What reading gave: the render (scene::Frame, the one scene model, scene/frame.h) and the file's
// own record beside it. The companions are kept as read (the probe is a render of its own);
// local::load_scene attaches what the pipeline needs of them to the frame.
struct Scene {
  scene::Frame frame;
  Rect data_window, display_window;        // of the beauty's part
  Rect window;                             // the one read (ReadOptions::window): the frame's size
  std::vector<std::string> views;          // of a multi-view OpenEXR, the default first; else empty
  std::string view;                        // the view read ("" without views)
  scene::ChannelMap channels;              // what the file's names mapped to
  std::vector<std::string> file_channels;  // every channel name in the file (all parts)
  std::optional<scene::Frame> probe;
  std::string probe_path;                  // read from, or looked for when absent
  std::string probe_also_looked_for;       // absent: the other place looked at (companion_order)
  std::optional<scene::Sidecar> sidecar;
  std::string sidecar_path;                // read from, or looked for when absent
  bool sidecar_foreign = false;            // a JSON file of another kind was there, and ignored
  std::size_t invalid_normals = 0;         // foreground pixels whose normal had no usable length
  std::vector<std::string> warnings;       // one line each, for the CLI to print
};

Scene read_scene(const std::string& path, const SceneRequest& req);

// Reads an equirectangular probe on its own: beauty and `passes`; DataError unless 2:1.
scene::Frame read_probe(const std::string& path, scene::PassSet passes);

// The conventional companion paths of a render: NAME.probe.exr and NAME.json beside NAME.exr.
std::string probe_path_for(const std::string& exr_path);
std::string sidecar_path_for(const std::string& exr_path);

// Where a render's companions are looked for, in order, the same for every face (single files,
// sequences, Python, the add-on). --explain prints it; docs/cgtmo.md documents it.
//   sidecar: --sidecar FILE, else NAME.json beside NAME.exr;
//   probe:   --probe FILE, else NAME.probe.exr beside NAME.exr, else the file the sidecar's
//            probe.file names (relative to the sidecar), so a render copied or renamed with
//            its companions keeps its probe.
inline constexpr const char* kCompanionOrder =
    "sidecar: --sidecar, else NAME.json; probe: --probe, else NAME.probe.exr, else the sidecar's probe.file";

}  // namespace cgtmo::io
