#include "cgtmo/local/scene_load.h"

#include <algorithm>
#include <cmath>

#include "cgtmo/color/input_space.h"
#include "cgtmo/color/luminance.h"
#include "cgtmo/io/chromaticities.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::local {

namespace {

// The camera's axes from its world matrix (Blender: looks along local -Z, +Y up; the matrix's
// columns are the local axes in world space) and the frame's angles.
scene::CameraView camera_view_of(const scene::Sidecar& sc) {
  scene::CameraView v;
  const auto& m = sc.camera.world_matrix;
  auto column = [&](int c, double sign, double* out) {
    const double x = m[0 * 4 + c], y = m[1 * 4 + c], z = m[2 * 4 + c];
    const double len = std::sqrt(x * x + y * y + z * z);
    if (!(len > 0) || !std::isfinite(len)) return false;
    out[0] = sign * x / len, out[1] = sign * y / len, out[2] = sign * z / len;
    return true;
  };
  const bool axes = column(0, 1.0, v.right) && column(1, 1.0, v.up) && column(2, -1.0, v.forward);
  v.fov_x = sc.camera.fov_x_rad;
  v.fov_y = sc.camera.fov_y_rad;
  if (!std::isfinite(v.fov_y) && sc.camera.width > 0 && sc.camera.height > 0)
    v.fov_y = 2.0 * repro::atan(repro::tan(v.fov_x / 2.0) * sc.camera.height / sc.camera.width);
  if (sc.probe) v.probe_heading = sc.probe->heading_rad;
  v.known = axes && v.fov_x > 0 && v.fov_y > 0 && std::isfinite(v.fov_y);
  return v;
}

}  // namespace

LoadResult load_scene(const LoadRequest& req) {
  using scene::Pass;
  io::SceneRequest sr;
  sr.required = Pass::Beauty;
  scene::PassSet optional = Pass::Depth;
  if (req.gbuffer) optional = optional | Pass::Position | Pass::Normal | Pass::Albedo;
  if (req.light_groups) optional = optional | Pass::LightGroups;
  sr.optional = optional;
  sr.layer = req.layer;
  sr.needed_by = req.needed_by;
  const io::Companion wanted = req.explicit_companions_optional ? io::Companion::Prefer : io::Companion::Auto;
  sr.probe = req.probe ? wanted : io::Companion::Skip;
  sr.probe_path = req.probe_path;
  sr.sidecar = req.sidecar ? wanted : io::Companion::Skip;
  sr.sidecar_path = req.sidecar_path;
  sr.read = req.read;
  sr.work = req.work;
  io::Scene sc = io::read_scene(req.path, sr);

  LoadResult out;
  scene::Frame& f = sc.frame;
  auto space_of = [&](const std::string& file, const std::string& label) {
    std::string disagreement;
    auto sp = color::InputSpace::resolve(req.config, req.colorspace, io::read_file_colour(file), &disagreement);
    if (!disagreement.empty()) out.warnings.push_back(label + disagreement);
    return sp;
  };
  const color::InputSpace space = space_of(req.path, "");
  out.input_space = space.description();
  space.apply(f.beauty, f.channels);
  for (auto& g : f.light_groups) space.apply(g.rgb, 3);
  if (!f.albedo.empty()) space.apply(f.albedo, 3);
  if (!f.emission.empty()) space.apply(f.emission, 3);
  if (sc.probe) space_of(sc.probe_path, "probe " + sc.probe_path + ": ").apply(sc.probe->beauty, sc.probe->channels);
  out.beauty_report = scene::sanitize(f);
  // The reader's frame is the model: what follows fills in the pipeline's part of it, in place.
  scene::Frame& s = f;
  s.source = req.path;
  // Peak memory: each light group's RGB goes as soon as its luminance exists.
  for (auto& g : s.light_groups) {
    g.luminance = color::luminance_plane(g.rgb, 3);
    std::vector<float>().swap(g.rgb);
  }
  if (sc.probe) {
    scene::sanitize(*sc.probe);
    s.probe.width = sc.probe->width;
    s.probe.height = sc.probe->height;
    s.probe.luminance = color::luminance_plane(sc.probe->beauty, sc.probe->channels);
    s.probe.source = sc.probe_path;
  } else if (req.probe) {
    const std::string also = sc.probe_also_looked_for.empty() ? "" : " nor '" + sc.probe_also_looked_for + "'";
    s.notes.push_back("no probe at " + sc.probe_path + (also.empty() ? "" : " (nor at " + sc.probe_also_looked_for + ")"));
    s.probe_absent = "'" + sc.probe_path + "' does not exist" + (also.empty() ? "" : ",") + also;
  }
  if (sc.sidecar) {
    s.has_sidecar = true;
    for (const auto& l : sc.sidecar->lights) s.lights.push_back({l.name, l.type, l.lightgroup, l.luminance});
    const double fp = sc.sidecar->camera.pixel_footprint_at_1m;
    if (std::isfinite(fp) && fp > 0) s.footprint_at_1m = fp;
    s.camera = camera_view_of(*sc.sidecar);
  } else if (req.sidecar) {
    if (!sc.sidecar_foreign) s.notes.push_back("no sidecar at " + sc.sidecar_path);
    s.sidecar_absent = "'" + sc.sidecar_path + (sc.sidecar_foreign ? "' is JSON of another kind, ignored" : "' does not exist");
    // Without light groups the statistics' own warning quotes sidecar_absent; with them, Lw_max
    // comes from the groups' passes, and this line says why.
    if (!s.light_groups.empty())
      out.companion_warnings.push_back("no sidecar (" + s.sidecar_absent + "): each light group's luminance is the maximum of its pass");
  }
  for (const auto& w : sc.warnings) s.notes.push_back(w);
  out.scene = std::move(f);
  return out;
}

void expose_scene(scene::Frame& s, double scale) {
  if (scale == 1.0) return;
  const float k = float(scale);
  // Colour only: alpha (the fourth channel) is coverage, not light.
  const int ch = s.channels;
  for (std::size_t i = 0; i < s.beauty.size(); ++i)
    if (i % std::size_t(ch) < 3) s.beauty[i] = std::min(s.beauty[i] * k, scene::kMaxInputValue);
  for (auto& g : s.light_groups)
    for (float& v : g.luminance) v *= k;
  for (float& v : s.probe.luminance) v *= k;
  for (auto& l : s.lights) l.luminance *= scale;  // NaN (unknown) stays NaN
}

}  // namespace cgtmo::local
