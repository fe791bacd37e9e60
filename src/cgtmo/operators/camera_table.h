#pragma once
// Camera response tables in the text layout of the Columbia DoRF database: for each curve a name
// line, an optional `graph` line, `I =` and the irradiances, `B =` and the intensities, both
// normalised to [0, 1].
#include <string>
#include <vector>

namespace cgtmo::operators {

struct CameraResponse {
  std::string name;
  std::vector<double> irradiance;  // non-decreasing, in [0, 1]
  std::vector<double> intensity;   // in [0, 1], same length
};

// Throws DataError naming the line when the text is not a valid table.
std::vector<CameraResponse> parse_dorf(const std::string& text, const std::string& source_name);

// The table shipped with cgtmo (data/camera/cgtmo-film.dorf, compiled in).
const std::vector<CameraResponse>& builtin_camera_responses();

// Intensity at irradiance e in [0, 1]: linear interpolation between the samples around e.
double sample_response(const CameraResponse& r, double e);

}  // namespace cgtmo::operators
