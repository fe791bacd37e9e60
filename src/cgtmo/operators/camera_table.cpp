#include "cgtmo/operators/camera_table.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cgtmo/errors.h"

namespace cgtmo::operators {

extern const char* const kBuiltinDorfText;  // generated from data/camera/cgtmo-film.dorf

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

bool starts_with_equals(const std::string& line, char key) {
  // "I =" or "I=" (any spacing)
  if (line.empty() || line[0] != key) return false;
  const std::string rest = trim(line.substr(1));
  return rest == "=";
}

}  // namespace

std::vector<CameraResponse> parse_dorf(const std::string& text, const std::string& source) {
  std::vector<CameraResponse> out;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  enum { Name, Irradiance, Intensity } state = Name;
  auto fail = [&](const std::string& why) {
    throw DataError(source + ":" + std::to_string(line_no) + ": " + why);
  };
  auto finish = [&]() {
    if (out.empty()) return;
    const CameraResponse& c = out.back();
    if (c.irradiance.size() < 2) fail("curve '" + c.name + "' has fewer than 2 samples");
    if (c.irradiance.size() != c.intensity.size())
      fail("curve '" + c.name + "' has " + std::to_string(c.irradiance.size()) + " irradiances but " +
           std::to_string(c.intensity.size()) + " intensities");
    for (std::size_t i = 0; i < c.irradiance.size(); ++i) {
      if (i && c.irradiance[i] < c.irradiance[i - 1]) fail("curve '" + c.name + "': irradiances decrease");
      if (c.irradiance[i] < 0 || c.irradiance[i] > 1 || c.intensity[i] < 0 || c.intensity[i] > 1)
        fail("curve '" + c.name + "': values outside [0, 1]");
    }
  };
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    if (starts_with_equals(line, 'I')) {
      if (out.empty() || state != Name) fail("'I =' without a curve name before it");
      state = Irradiance;
      continue;
    }
    if (starts_with_equals(line, 'B')) {
      if (state != Irradiance) fail("'B =' before 'I ='");
      state = Intensity;
      continue;
    }
    const bool numeric = std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-' || line[0] == '.' || line[0] == '+';
    if (numeric && state != Name) {
      std::istringstream nums(line);
      std::string tok;
      while (nums >> tok) {
        char* end = nullptr;
        const double v = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end != '\0' || !std::isfinite(v)) fail("not a number: '" + tok + "'");
        (state == Irradiance ? out.back().irradiance : out.back().intensity).push_back(v);
      }
      continue;
    }
    if (line == "graph" && state == Name && !out.empty() && out.back().irradiance.empty()) continue;
    if (numeric) fail("numbers before 'I ='");
    // A new curve's name.
    finish();
    out.push_back(CameraResponse{line, {}, {}});
    state = Name;
  }
  finish();
  if (out.empty()) throw DataError(source + ": no camera response curve found");
  return out;
}

const std::vector<CameraResponse>& builtin_camera_responses() {
  static const std::vector<CameraResponse> table = parse_dorf(kBuiltinDorfText, "builtin");
  return table;
}

double sample_response(const CameraResponse& r, double e) {
  const auto& irr = r.irradiance;
  if (!(e > irr.front())) return r.intensity.front();
  if (e >= irr.back()) return r.intensity.back();
  // First sample above e; the one before it is the lower neighbour.
  const std::size_t hi = std::upper_bound(irr.begin(), irr.end(), e) - irr.begin();
  const std::size_t lo = hi - 1;
  const double span = irr[hi] - irr[lo];
  const double t = span > 0 ? (e - irr[lo]) / span : 0.0;
  return r.intensity[lo] + (r.intensity[hi] - r.intensity[lo]) * t;
}

}  // namespace cgtmo::operators
