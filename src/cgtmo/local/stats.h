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
//           Region (AdaptationOptions::region): the whole sphere (the paper), the view (the probe
//           weighted by a lobe over the camera's frame, view_weights), or the image itself. The
//           view's value is kept within `factor` of the image's own statistic: beyond it, only
//           (1 - blend) of the remaining log-difference is kept (a geometric blend towards the
//           image). Defaults (docs/cgtmo.md, measured): lobe 10 degrees, factor 1 and blend 0.5,
//           so Lw_a is the geometric mean of the view's and the image's values; --explain says
//           when the two differ by more than kViewDisagreement.
// Every fallback adds a warning naming what was missing and what was used instead.
#include <string>
#include <vector>

#include "cgtmo/scene/frame.h"

namespace cgtmo::local {

enum class Adaptation { Harmonic, LogAverage };
Adaptation adaptation_from_name(const std::string& name);  // "harmonic" | "log"; UsageError otherwise
const char* adaptation_name(Adaptation a);

// Where Lw_a is measured: the probe weighted towards the camera's frame, the whole probe
// sphere (the paper), or the frame's own pixels.
enum class AdaptationRegion { View, Sphere, Image };
AdaptationRegion adaptation_region_from_name(const std::string& name);  // "view" | "probe" | "image"
const char* adaptation_region_name(AdaptationRegion r);

struct AdaptationOptions {
  Adaptation mean = Adaptation::LogAverage;
  AdaptationRegion region = AdaptationRegion::View;
  double lobe_deg = 10;  // Gaussian sigma of the view lobe's fall-off beyond the frame's edge
  double factor = 1;     // how far (a ratio) the view may sit from the image's statistic untouched
  double blend = 0.5;    // share of the log-difference beyond `factor` taken back towards the image
  // The scene was made this much brighter (--exposure) before `lum` was taken. The image's means
  // are taken at the scene's own level and scaled back (k * mean(lum / k)), so the floor under
  // black pixels does not break the rule that the statistics scale with the exposure.
  double exposure = 1;
};

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
  double view_harmonic = 0, view_log_average = 0;  // the probe under the view lobe; 0: not computed
  double view_in_frame_share = 0;       // share of the lobe's weight that falls inside the frame
  double view_unblended = 0;            // the view's statistic before the blend; 0: not used
  bool view_blended = false;            // view and image disagreed by more than the factor
  std::string adaptation_note;          // how Lw_a was chosen, for --explain
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

// Weight of each probe pixel for the camera's view, solid angle included: 1 for directions inside
// the frame, exp(-d^2 / (2 sigma^2)) for those an angle d beyond its edge (sigma = lobe_deg),
// times the pixel's solid angle. Empty when the camera is unknown.
std::vector<float> view_weights(int probe_width, int probe_height, const scene::CameraView& camera, double lobe_deg);

// Lw_a after the view/image blend: the view's value when within `factor` of the image's, else
// image * f^(sign) * (r / f)^(sign (1 - blend)) with r the ratio view / image.
double blend_towards_image(double view, double image, double factor, double blend);

// Beyond this ratio between the view's and the image's statistics, --explain says they disagree.
inline constexpr double kViewDisagreement = 2;

// lum: the beauty's luminance (width*height, sanitised).
SceneStats compute_scene_stats(const scene::Frame& scene, const std::vector<float>& lum, const AdaptationOptions& adaptation);
inline SceneStats compute_scene_stats(const scene::Frame& scene, const std::vector<float>& lum, Adaptation mean) {
  AdaptationOptions o;
  o.mean = mean;
  return compute_scene_stats(scene, lum, o);
}

}  // namespace cgtmo::local
