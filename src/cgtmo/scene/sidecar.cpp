#include "cgtmo/scene/sidecar.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::scene {

namespace {

using json = nlohmann::json;

// Far beyond any render (a 1M-pixel-wide frame), well inside int.
constexpr int kMaxResolution = 1 << 20;

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw DataError("sidecar '" + origin + "': " + what);
}

const char* kind_of(const json& j) {
  switch (j.type()) {
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    default: return j.is_number() ? "a number" : "another kind of value";
  }
}

const json& need(const json& obj, const char* key, const std::string& where, const std::string& origin) {
  if (!obj.is_object() || !obj.contains(key)) fail(origin, where + " lacks '" + key + "'");
  return obj.at(key);
}

double number(const json& v, const std::string& where, const std::string& origin) {
  if (!v.is_number()) fail(origin, where + " is not a number");
  return v.get<double>();
}

std::string text(const json& v, const std::string& where, const std::string& origin) {
  if (!v.is_string()) fail(origin, where + " is not a string");
  return v.get<std::string>();
}

double optional_number(const json& obj, const char* key, const std::string& where, const std::string& origin) {
  if (!obj.contains(key) || obj.at(key).is_null()) return kUnset;
  return number(obj.at(key), where + "." + key, origin);
}

std::vector<double> numbers(const json& v, const std::string& where, const std::string& origin) {
  if (!v.is_array()) fail(origin, where + " is not an array");
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], where + "[" + std::to_string(i) + "]", origin));
  return out;
}

std::pair<int, int> resolution(const json& v, const std::string& where, const std::string& origin) {
  const std::vector<double> r = numbers(v, where, origin);
  // Range first: converting a double beyond int's range is undefined behaviour.
  auto pixels = [](double v) { return v >= 1 && v <= kMaxResolution && v == std::floor(v); };
  if (r.size() != 2 || !pixels(r[0]) || !pixels(r[1]))
    fail(origin, where + " is not [width, height] with integers in [1, " + std::to_string(kMaxResolution) + "]");
  return {int(r[0]), int(r[1])};
}

CameraInfo parse_camera(const json& j, const std::string& origin) {
  CameraInfo c;
  const json& m = need(j, "world_matrix", "camera", origin);
  if (!m.is_array() || m.size() != 4) fail(origin, "camera.world_matrix is not a 4x4 array");
  for (int r = 0; r < 4; ++r) {
    const std::vector<double> row = numbers(m[r], "camera.world_matrix[" + std::to_string(r) + "]", origin);
    if (row.size() != 4) fail(origin, "camera.world_matrix is not a 4x4 array");
    for (int k = 0; k < 4; ++k) c.world_matrix[r * 4 + k] = row[k];
  }
  c.fov_x_rad = number(need(j, "fov_x_rad", "camera", origin), "camera.fov_x_rad", origin);
  if (!(c.fov_x_rad > 0 && c.fov_x_rad < 3.15)) fail(origin, "camera.fov_x_rad is not in (0, pi]");
  std::tie(c.width, c.height) = resolution(need(j, "resolution", "camera", origin), "camera.resolution", origin);
  c.fov_y_rad = optional_number(j, "fov_y_rad", "camera", origin);
  c.lens_mm = optional_number(j, "lens_mm", "camera", origin);
  c.sensor_width_mm = optional_number(j, "sensor_width_mm", "camera", origin);
  c.sensor_height_mm = optional_number(j, "sensor_height_mm", "camera", origin);
  c.clip_start = optional_number(j, "clip_start", "camera", origin);
  c.clip_end = optional_number(j, "clip_end", "camera", origin);
  c.pixel_footprint_at_1m = optional_number(j, "pixel_footprint_at_1m", "camera", origin);
  if (std::isnan(c.pixel_footprint_at_1m)) c.pixel_footprint_at_1m = 2.0 * repro::tan(c.fov_x_rad / 2.0) / c.width;
  return c;
}

LightInfo parse_light(const json& j, std::size_t index, const std::string& origin) {
  const std::string where = "lights[" + std::to_string(index) + "]";
  if (!j.is_object()) fail(origin, where + " is not an object");
  LightInfo l;
  l.name = text(need(j, "name", where, origin), where + ".name", origin);
  l.type = text(need(j, "type", where, origin), where + ".type", origin);
  l.lightgroup = text(need(j, "lightgroup", where, origin), where + ".lightgroup", origin);
  l.luminance = number(need(j, "luminance", where, origin), where + ".luminance", origin);
  if (!(l.luminance >= 0) || std::isinf(l.luminance)) fail(origin, where + ".luminance is negative or not finite");
  if (j.contains("color")) {
    const std::vector<double> c = numbers(j.at("color"), where + ".color", origin);
    if (c.size() != 3) fail(origin, where + ".color is not [r, g, b]");
    l.color = {c[0], c[1], c[2]};
  }
  l.power = optional_number(j, "power", where, origin);
  l.strength = optional_number(j, "strength", where, origin);
  l.radius = optional_number(j, "radius", where, origin);
  l.angle = optional_number(j, "angle", where, origin);
  if (j.contains("size")) l.size = numbers(j.at("size"), where + ".size", origin);
  if (j.contains("in_frame") && !j.at("in_frame").is_null()) {
    if (!j.at("in_frame").is_boolean()) fail(origin, where + ".in_frame is not true or false");
    l.in_frame = j.at("in_frame").get<bool>();
  }
  return l;
}

}  // namespace

const LightInfo* Sidecar::light_for_group(const std::string& group) const {
  for (const auto& l : lights)
    if (l.lightgroup == group) return &l;
  return nullptr;
}

static Sidecar parse_sidecar_unchecked(const std::string& content, const std::string& origin) {
  json j;
  try {
    j = json::parse(content);
  } catch (const json::exception& e) {
    // parse_error, or out_of_range for a number beyond double (found by fuzz_sidecar).
    // nlohmann's message carries the byte position; keep its first line.
    std::string msg = e.what();
    fail(origin, "not JSON (" + msg.substr(0, msg.find('\n')) + ")");
  }
  if (!j.is_object()) fail(origin, std::string("not a JSON object (") + kind_of(j) + ")");
  Sidecar s;
  s.path = origin;
  if (j.contains("scene") && j.at("scene").is_string()) s.scene = j.at("scene").get<std::string>();
  s.camera = parse_camera(need(j, "camera", "the top level", origin), origin);
  const json& lights = need(j, "lights", "the top level", origin);
  if (!lights.is_array()) fail(origin, "'lights' is not an array");
  for (std::size_t i = 0; i < lights.size(); ++i) s.lights.push_back(parse_light(lights[i], i, origin));
  if (j.contains("probe") && !j.at("probe").is_null()) {
    const json& p = j.at("probe");
    ProbeInfo pi;
    pi.projection = text(need(p, "projection", "probe", origin), "probe.projection", origin);
    if (p.contains("file")) pi.file = text(p.at("file"), "probe.file", origin);
    if (p.contains("resolution")) std::tie(pi.width, pi.height) = resolution(p.at("resolution"), "probe.resolution", origin);
    pi.heading_rad = optional_number(p, "heading_rad", "probe", origin);
    s.probe = pi;
  }
  if (j.contains("background_depth")) s.background_depth = number(j.at("background_depth"), "background_depth", origin);
  return s;
}

Sidecar parse_sidecar(const std::string& content, const std::string& origin) {
  try {
    return parse_sidecar_unchecked(content, origin);
  } catch (const json::exception& e) {
    // A value of a type the checks above did not expect: still one DataError, never a crash.
    std::string msg = e.what();
    fail(origin, "unexpected content (" + msg.substr(0, msg.find('\n')) + ")");
  }
  return {};
}

static std::string read_sidecar_text(const std::string& path) {
  io::require_input_file(path, "sidecar ");  // a FIFO or device would block or never end
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError("sidecar '" + path + "': cannot open");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw DataError("sidecar '" + path + "': read error");
  return ss.str();
}

Sidecar read_sidecar(const std::string& path) { return parse_sidecar(read_sidecar_text(path), path); }

bool is_foreign_json(const std::string& text) {
  const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  // Not JSON, or JSON that is not an object (an array, a string, a number, null): a broken
  // sidecar, reported as such. Another tool's file is a document: an object of its own fields.
  if (j.is_discarded() || !j.is_object()) return false;
  // Ours says so ("format": "cgtmo-scene-sidecar"); a file without a format is ours only when it
  // has both of our required keys: another tool's JSON with a "camera" of its own is foreign.
  const auto format = j.find("format");
  if (format != j.end()) return !(format->is_string() && format->get<std::string>() == kSidecarFormat);
  return !(j.contains("camera") && j.contains("lights"));
}

std::optional<Sidecar> read_sidecar_unless_foreign(const std::string& path) {
  const std::string text = read_sidecar_text(path);
  if (is_foreign_json(text)) return std::nullopt;
  return parse_sidecar(text, path);
}

}  // namespace cgtmo::scene
