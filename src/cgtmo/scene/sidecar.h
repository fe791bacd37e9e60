#pragma once
// The JSON sidecar a render carries (scripts/blender/render_scene.py writes it): the camera, the
// adaptation probe's projection, and every emitter with the luminance of its emitted radiance in
// the render's units. The EXR header holds none of this (docs/platform.md).
//
// Required fields (a DataError names the first one missing):
//   camera.world_matrix (4x4), camera.fov_x_rad, camera.resolution [w, h],
//   lights[] with name, type, lightgroup, luminance.
// Everything else is optional and left NaN / empty when absent.
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cgtmo::scene {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct CameraInfo {
  std::array<double, 16> world_matrix{};  // row-major; Blender: looks along local -Z, +Y up
  double fov_x_rad = kUnset, fov_y_rad = kUnset;
  double lens_mm = kUnset, sensor_width_mm = kUnset, sensor_height_mm = kUnset;
  int width = 0, height = 0;
  double clip_start = kUnset, clip_end = kUnset;
  // World-space width of one pixel at distance 1 (2 tan(fov_x / 2) / width): the CG-TMO
  // position sigma is this times the distance times sigma_g.
  double pixel_footprint_at_1m = kUnset;
};

struct LightInfo {
  std::string name, type, lightgroup;  // type: POINT, SPOT, AREA, SUN, MESH, WORLD
  std::array<double, 3> color{1.0, 1.0, 1.0};
  double power = kUnset;      // watts (POINT, SPOT, AREA)
  double strength = kUnset;   // SUN irradiance, MESH/WORLD emission strength
  double radius = kUnset;     // POINT, SPOT
  double angle = kUnset;      // SUN angular diameter, radians
  std::vector<double> size;   // AREA size_x, size_y; MESH bounding box
  double luminance = kUnset;  // Rec.709 Y of the emitted radiance, in the render's units
  std::optional<bool> in_frame;  // directly seen by the camera (absent for the world)
};

struct ProbeInfo {
  std::string file;          // relative to the sidecar's folder
  std::string projection;    // "equirectangular"
  int width = 0, height = 0;
  double heading_rad = kUnset;
};

struct Sidecar {
  std::string path;  // where it was read from ("" when parsed from text)
  std::string scene;
  CameraInfo camera;
  std::optional<ProbeInfo> probe;
  std::vector<LightInfo> lights;
  double background_depth = 1e10;

  // The light whose light group is `group`, or nullptr.
  const LightInfo* light_for_group(const std::string& group) const;
};

// Parses sidecar text; `origin` names it in errors. Throws DataError: not JSON, not an object,
// a required field missing or of the wrong type.
Sidecar parse_sidecar(const std::string& text, const std::string& origin);

// Reads and parses a file. Throws DataError (missing, unreadable, invalid).
Sidecar read_sidecar(const std::string& path);

// The "format" value of cgtmo's sidecars (scripts/blender/render_scene.py writes it).
inline constexpr const char* kSidecarFormat = "cgtmo-scene-sidecar";

// True when `text` is a JSON object of another tool, which the readers ignore with a warning: its
// "format" is another, or it has no "format" and lacks "camera" or "lights" (another tool's file
// may well have a "camera" of its own). A broken sidecar is not foreign, and read_sidecar reports
// what is wrong with it (a DataError): not JSON, JSON that is not an object (an array, a string, a
// number, null: bad data, not a document of another tool), or a field present but wrong.
bool is_foreign_json(const std::string& text);

// read_sidecar, except that a foreign file (is_foreign_json) gives nullopt instead of an error.
std::optional<Sidecar> read_sidecar_unless_foreign(const std::string& path);

}  // namespace cgtmo::scene
