#pragma once
// Scene statistics for Drago's curve from the 3-D scene rather than the image (CG-TMO, Sec. 3.4):
//   Lw_max: per pixel the light group contributing most (the paper's buffer M); Lw_max is the
//           largest emitted luminance among the lights that win at least one pixel of M, from the
//           sidecar, or measured as the maximum of the group's pass when the sidecar lacks it.
//           One light: no analysis (that light's luminance). Neither groups nor lights: the image.
//   Lw_a:   from the 64x32 equirectangular probe, weighted by solid angle, over the directions
//           that receive light (luminance above kMeanFloor; a black world is no stimulus): the
//           harmonic mean (the paper) or the log-average (Drago's paper); from the image when
//           the probe is missing or black. docs/cgtmo.md explains the default.
// Every fallback adds a warning naming what was missing and what was used instead.
#include <string>
#include <vector>

#include "cgtmo/cgtmo/scene_data.h"

namespace cgtmo::local {

enum class Adaptation { Harmonic, LogAverage };
Adaptation adaptation_from_name(const std::string& name);  // "harmonic" | "log"; UsageError otherwise
const char* adaptation_name(Adaptation a);

// The floor under luminances in both means (pfstmo_drago03's epsilon), so black pixels count
// without making the harmonic mean 0 or the log-average -inf.
inline constexpr double kMeanFloor = 1e-4;

struct GroupUse {
  std::string name;
  std::size_t pixels_in_m = 0;  // pixels where this group contributes most
  double emitted = 0;           // its emitted luminance as used
  std::string emitted_source;   // "sidecar" or "measured (pass maximum)"
};

struct SceneStats {
  double lw_max = 1, lw_a = 1;
  std::string lw_max_source, lw_a_source;
  double image_max = 0;                 // beauty's maximum luminance (finite pixels)
  double image_harmonic = 0, image_log_average = 0;
  double probe_harmonic = 0, probe_log_average = 0;  // 0 when there is no usable probe
  double probe_dark_fraction = 0;       // solid-angle share of probe directions left out (black)
  bool light_analysis = false;          // M was built
  std::string light_analysis_note;      // why it was skipped, or what it found
  std::vector<GroupUse> groups;         // light groups with their M counts (when analysed)
  std::vector<std::string> warnings;
};

// Weighted means of luminance (weights may be null: uniform). Values below kMeanFloor count as it.
double harmonic_mean(const float* lum, const float* weights, std::size_t n);
double log_average(const float* lum, const float* weights, std::size_t n);
// Solid angle of each row of an equirectangular image with `height` rows (row 0 at the zenith),
// up to a constant: cos(latitude) at the row centre.
std::vector<float> equirect_weights(int width, int height);

// lum: the beauty's luminance (width*height, sanitised).
SceneStats compute_scene_stats(const SceneData& scene, const std::vector<float>& lum, Adaptation adaptation);

}  // namespace cgtmo::local
