#include "cgtmo/io/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_parts.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"

namespace cgtmo::io {

namespace fs = std::filesystem;
using scene::Pass;
using scene::PassSet;

namespace {

// Depth where a part has no pixels: Blender's background value (>= scene::kBackgroundDepth).
constexpr float kOutsideDepth = 1e10f;

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// Where each channel of the chosen view lives across the file's parts (first occurrence wins).
// In a multi-view file the channels of other views are left out and the view's own are named
// without their view component ("right.R" is "R"), so the pass mapping sees one plain image.
struct PartIndex {
  std::vector<Part> parts;
  std::map<std::string, int> part_of;          // channel name -> index into parts
  std::map<std::string, std::string> in_file;  // channel name -> its name in the file
  std::vector<std::string> all_names;          // in file order, parts concatenated
  std::vector<std::string> views;              // of a multi-view file; the default first
  std::string view;                            // the one read ("" without views)

  PartIndex(const std::string& path, const std::string& wanted_view) : parts(read_parts(path)), views(views_of(parts)) {
    if (views.empty() && !wanted_view.empty())
      throw DataError("'" + path + "': no view '" + wanted_view + "': the file is not multi-view (--exr-view)");
    if (!views.empty()) {
      view = wanted_view.empty() ? views[0] : wanted_view;
      if (std::find(views.begin(), views.end(), view) == views.end()) {
        std::string list;
        for (const auto& v : views) list += (list.empty() ? "" : ", ") + v;
        throw DataError("'" + path + "': no view '" + view + "' (views: " + list + ")");
      }
    }
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const Part& part = parts[p];
      if (!part.view.empty() && part.view != view) continue;
      for (const auto& n : part.names) {
        if (!part.multi_view.empty() && view_of_channel(n, part.multi_view) != view) continue;
        const std::string name = part.multi_view.empty() ? n : without_view(n, part.multi_view);
        if (part_of.emplace(name, int(p)).second) {
          all_names.push_back(name);
          in_file.emplace(name, n);
        }
      }
    }
  }
};

// Reads each of `sets` (its channel names possibly spread over parts) as an interleaved buffer over
// `window`, decoding each part once for all of them. A part's data window is placed on the frame's
// window: what lies outside the window is dropped, and where the part has no pixels set i reads
// fills[i] (zero for colour, the background depth for depth).
std::vector<std::vector<float>> read_name_sets(const std::string& path, const PartIndex& idx,
                                               const std::vector<std::vector<std::string>>& sets,
                                               const std::vector<float>& fills, const Rect& window) {
  const std::size_t npx = std::size_t(window.width) * std::size_t(window.height);
  struct InPart {
    std::vector<std::vector<std::string>> names;     // per set: its channels in this part
    std::vector<std::vector<std::size_t>> positions;  // and where they go in the set
  };
  std::map<int, InPart> by_part;
  for (std::size_t i = 0; i < sets.size(); ++i)
    for (std::size_t j = 0; j < sets[i].size(); ++j) {
      InPart& in = by_part[idx.part_of.at(sets[i][j])];
      in.names.resize(sets.size());
      in.positions.resize(sets.size());
      in.names[i].push_back(idx.in_file.at(sets[i][j]));
      in.positions[i].push_back(j);
    }
  std::vector<std::vector<float>> out(sets.size());
  for (auto& [p, in] : by_part) {
    const Part& part = idx.parts[std::size_t(p)];
    std::vector<std::vector<float>> bufs = read_part_channel_sets(path, part, in.names);
    for (std::size_t i = 0; i < sets.size(); ++i) {
      const std::size_t k = sets[i].size(), m = in.names[i].size();
      if (m == 0) continue;
      // The usual single-part render whose data window is the frame: the part's buffer is the
      // pass, so no second copy of it is held while the frame is read (peak memory).
      if (m == k && part.data == window) {
        out[i] = std::move(bufs[i]);
        continue;
      }
      if (out[i].empty()) out[i].assign(npx * k, fills[i]);
      if (m == k) {
        place(bufs[i].data(), part.data, out[i].data(), window, int(k));
        continue;
      }
      // Some of the set's channels: through a buffer of the window, then into their places.
      std::vector<float> on_window(npx * m, fills[i]);
      place(bufs[i].data(), part.data, on_window.data(), window, int(m));
      std::vector<float>().swap(bufs[i]);
      for (std::size_t px = 0; px < npx; ++px)
        for (std::size_t j = 0; j < m; ++j) out[i][px * k + in.positions[i][j]] = on_window[px * m + j];
    }
  }
  return out;
}

struct FrameResult {
  scene::Frame frame;
  Rect data_window, display_window, window;
  std::vector<std::string> views;
  std::string view;
  scene::ChannelMap map;
  std::vector<std::string> names;
  std::size_t invalid_normals = 0;
  std::vector<std::string> warnings;
};

FrameResult read_frame(const std::string& path, const std::string& layer, PassSet required, PassSet optional,
                       const std::string& needed_by, const ReadOptions& ro, const FrameWork& work) {
  const PartIndex idx(path, ro.view);
  FileChannels fc;
  fc.names = idx.all_names;
  fc.path = path;
  const BeautyChannels b = find_beauty(fc, layer);  // DataError listing the layers when none
  FrameResult r;
  r.names = idx.all_names;
  r.views = idx.views;
  r.view = idx.view;
  r.map = scene::map_channels(idx.all_names, b.prefix);
  scene::apply_overrides(r.map, idx.all_names, ro.passes, path);
  const Part& beauty_part = idx.parts[std::size_t(idx.part_of.at(b.r))];
  r.data_window = beauty_part.data;
  r.display_window = beauty_part.display;
  r.window = ro.window == Window::Data ? beauty_part.data : beauty_part.display;
  scene::Frame& f = r.frame;
  f.width = r.window.width;
  f.height = r.window.height;
  f.source = path;
  f.layer = b.prefix;
  const PassSet wanted = required | optional | Pass::Beauty;
  for (Pass p : scene::passes_in(required)) {
    if (!r.map.has(p))
      throw DataError("'" + path + "': no " + scene::pass_name(p) + " pass, needed by " + needed_by + " (looked for " +
                      scene::ChannelMap::expected_names(p, b.prefix) + "; the file has: " + layers_of(idx.all_names) + ")");
  }
  const std::size_t npx = f.pixel_count();
  // Every pass to read, decoded in one pass over the file.
  std::vector<std::vector<std::string>> sets;
  std::vector<float> fills;
  auto ask = [&](bool when, const std::vector<std::string>& names, float fill = 0.0f) {
    if (!when) return -1;
    sets.push_back(names);
    fills.push_back(fill);
    return int(sets.size()) - 1;
  };
  auto has = [&](Pass p) { return wanted.has(p) && r.map.has(p); };
  // Where a pass has no pixels: no light (0), no geometry (depth 1e10, Blender's background:
  // position and normal (0,0,0) as Blender writes there).
  const int at_beauty = ask(wanted.has(Pass::Beauty), r.map.beauty);
  const int at_depth = ask(has(Pass::Depth), {r.map.depth}, kOutsideDepth);
  const int at_position = ask(has(Pass::Position), r.map.position);
  const int at_albedo = ask(has(Pass::Albedo), r.map.albedo);
  const int at_emission = ask(has(Pass::Emission), r.map.emission);
  const int at_normal = ask(has(Pass::Normal), r.map.normal);
  std::vector<int> at_groups;
  if (wanted.has(Pass::LightGroups))
    for (const auto& g : r.map.light_groups) at_groups.push_back(ask(true, g.rgb));
  // The window, not the data, sizes the frame and the caller's work on it: a display window far
  // larger than the stored pixels (no byte of the file bounds it) is held to the memory budget
  // with both, before anything is allocated by it.
  std::size_t values = 0;
  for (const auto& set : sets) values += set.size();
  auto frame_window = [&ro](const Rect& r, bool display) {
    return FrameWindow{display ? "display" : "data", r.x, r.y, r.width, r.height};
  };
  check_frame_size(path, frame_window(r.window, ro.window == Window::Display), frame_window(r.data_window, false), int(values),
                   work);
  std::vector<std::vector<float>> data = read_name_sets(path, idx, sets, fills, r.window);
  auto take = [&](int at) { return at < 0 ? std::vector<float>() : std::move(data[std::size_t(at)]); };
  if (at_beauty >= 0) {
    f.channels = int(r.map.beauty.size());
    f.beauty = take(at_beauty);
  }
  if (at_depth >= 0) {
    f.depth = take(at_depth);
    f.background.resize(npx);
    for (std::size_t i = 0; i < npx; ++i) f.background[i] = scene::is_background_depth(f.depth[i]);
  }
  f.position = take(at_position);
  f.albedo = take(at_albedo);
  f.emission = take(at_emission);
  if (at_normal >= 0) {
    f.normal = take(at_normal);
    f.normal_valid.assign(npx, 1);
    for (std::size_t i = 0; i < npx; ++i) {
      float* n = &f.normal[3 * i];
      const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
      if (scene::normal_has_direction(len)) {
        for (int c = 0; c < 3; ++c) n[c] = float(n[c] / len);
      } else {
        n[0] = n[1] = n[2] = 0.0f;
        f.normal_valid[i] = 0;
        if (f.background.empty() || !f.background[i]) ++r.invalid_normals;
      }
    }
  }
  if (wanted.has(Pass::LightGroups)) {
    for (std::size_t k = 0; k < r.map.light_groups.size(); ++k) {
      const auto& g = r.map.light_groups[k];
      scene::LightGroupPlane lg;
      lg.name = g.name;
      lg.rgb = take(at_groups[k]);
      lg.all_zero = std::all_of(lg.rgb.begin(), lg.rgb.end(), [](float v) { return v == 0.0f; });
      if (lg.all_zero) r.warnings.push_back("light group '" + g.name + "' is zero in every pixel");
      f.light_groups.push_back(std::move(lg));
    }
  }
  if (r.invalid_normals)
    r.warnings.push_back(std::to_string(r.invalid_normals) + " foreground pixels have a zero-length normal (marked invalid)");
  return r;
}

std::string strip_exr(const std::string& path) {
  const fs::path p(path);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".exr" ? (p.parent_path() / p.stem()).string() : path;
}

// Something is at `p` (symlinks followed): a companion that is a folder, FIFO or device is then
// refused by its reader with a message saying so, rather than passed over as absent.
bool exists(const std::string& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

}  // namespace

std::string probe_path_for(const std::string& exr_path) { return strip_exr(exr_path) + ".probe.exr"; }
std::string sidecar_path_for(const std::string& exr_path) { return strip_exr(exr_path) + ".json"; }

scene::Frame read_probe(const std::string& path, PassSet passes) {
  FrameResult r = read_frame(path, "", Pass::Beauty | passes, PassSet(), "the adaptation probe", ReadOptions{}, FrameWork{});
  if (r.frame.width != 2 * r.frame.height)
    throw DataError("probe '" + path + "' is " + size_text(r.frame.width, r.frame.height) +
                    ": an equirectangular probe is twice as wide as high (e.g. 64x32)");
  return std::move(r.frame);
}

Scene read_scene(const std::string& path, const SceneRequest& req) {
  Scene s;
  FrameResult r = read_frame(path, req.layer, req.required, req.optional, req.needed_by, req.read, req.work);
  s.frame = std::move(r.frame);
  s.data_window = r.data_window;
  s.display_window = r.display_window;
  s.window = r.window;
  s.views = std::move(r.views);
  s.view = r.view;
  s.channels = std::move(r.map);
  s.file_channels = std::move(r.names);
  s.invalid_normals = r.invalid_normals;
  s.warnings = std::move(r.warnings);

  if (req.sidecar != Companion::Skip) {
    s.sidecar_path = req.sidecar_path.empty() ? sidecar_path_for(path) : req.sidecar_path;
    const bool explicit_path = !req.sidecar_path.empty();
    if (exists(s.sidecar_path)) s.sidecar = scene::read_sidecar_unless_foreign(s.sidecar_path);
    if (exists(s.sidecar_path) && !s.sidecar) {
      s.sidecar_foreign = true;
      s.warnings.push_back("sidecar '" + s.sidecar_path + "' is JSON of another kind (no camera, no lights): ignored");
    } else if (s.sidecar) {
      const scene::CameraInfo& cam = s.sidecar->camera;
      // The camera's resolution is the display window's, whichever window is read.
      if (cam.width != s.display_window.width || cam.height != s.display_window.height)
        throw DataError("sidecar '" + s.sidecar_path + "' describes a " + size_text(cam.width, cam.height) +
                        " render, but '" + path + "' is " + size_text(s.display_window.width, s.display_window.height));
      if (!s.frame.light_groups.empty()) {
        for (const auto& l : s.sidecar->lights)
          if (std::none_of(s.frame.light_groups.begin(), s.frame.light_groups.end(),
                           [&](const scene::LightGroupPlane& g) { return g.name == l.lightgroup; }))
            s.warnings.push_back("sidecar light '" + l.name + "' (group '" + l.lightgroup + "') has no light group pass");
        for (const auto& g : s.frame.light_groups)
          if (!s.sidecar->light_for_group(g.name))
            s.warnings.push_back("light group pass '" + g.name + "' has no light in the sidecar");
      }
    } else if (req.sidecar == Companion::Require || (explicit_path && req.sidecar != Companion::Prefer)) {
      throw DataError("sidecar '" + s.sidecar_path + "': no such file (needed by " + req.needed_by + ")");
    }
  }

  if (req.probe != Companion::Skip) {
    const bool explicit_path = !req.probe_path.empty();
    // The order of kCompanionOrder (scene_reader.h).
    s.probe_path = explicit_path ? req.probe_path : probe_path_for(path);
    if (!explicit_path && !exists(s.probe_path) && s.sidecar && s.sidecar->probe && !s.sidecar->probe->file.empty()) {
      const std::string named = (fs::path(s.sidecar_path).parent_path() / s.sidecar->probe->file).string();
      if (fs::path(named).lexically_normal() != fs::path(s.probe_path).lexically_normal()) {
        s.probe_also_looked_for = s.probe_path;
        s.probe_path = named;
      }
    }
    if (exists(s.probe_path)) {
      if (s.sidecar && s.sidecar->probe) {
        const scene::ProbeInfo& pi = *s.sidecar->probe;
        if (pi.projection != "equirectangular")
          throw DataError("sidecar '" + s.sidecar_path + "': probe projection '" + pi.projection +
                          "' is not supported (only equirectangular)");
      }
      scene::Frame probe = read_probe(s.probe_path, req.probe_passes);
      if (s.sidecar && s.sidecar->probe && s.sidecar->probe->width > 0 &&
          (s.sidecar->probe->width != probe.width || s.sidecar->probe->height != probe.height))
        throw DataError("probe '" + s.probe_path + "' is " + size_text(probe.width, probe.height) + " but sidecar '" +
                        s.sidecar_path + "' says " + size_text(s.sidecar->probe->width, s.sidecar->probe->height));
      for (const auto& g : probe.light_groups)
        if (g.all_zero) s.warnings.push_back("probe light group '" + g.name + "' is zero in every pixel");
      s.probe = std::move(probe);
    } else if (req.probe == Companion::Require || (explicit_path && req.probe != Companion::Prefer)) {
      throw DataError("probe '" + s.probe_path + "': no such file (needed by " + req.needed_by + ")");
    }
  }
  return s;
}

}  // namespace cgtmo::io
