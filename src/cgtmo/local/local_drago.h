#pragma once
#include <functional>
// CG-TMO (Banterle, Artusi, Banterle, Scopigno, EUSIPCO 2014): Drago's curve applied locally,
//     Ld = TC(L_base) * (L_w / L_base),
// with L_base an edge-aware filter of the log10 luminance (the G-buffer cross-bilateral filter,
// its approximations, the luminance-only bilateral, or Farbman's WLS for the WLS-TMO baseline)
// and TC Drago's curve (operators/drago_curve.h) with Lw_max and Lw_a from the scene (stats.h).
// Colour is restored from Ld / Lw with a saturation exponent; background pixels (no geometry)
// are neither sources nor filtered, so they get the global curve: TC(L_w).
#include <string>
#include <vector>

#include "cgtmo/scene/frame.h"
#include "cgtmo/local/pre_compression.h"
#include "cgtmo/local/stats.h"
#include "cgtmo/filters/guide.h"
#include "cgtmo/filters/wls.h"

namespace cgtmo::local {

struct LocalOptions {
  std::string filter = "fast";  // a name of filters::filter_table()
  double b = 0.85;              // Drago's bias
  double ld_max = 100;          // display maximum, cd/m^2 (100: Lw_max maps to 1)
  double saturation = 1.0;      // out = Ld * (C / Lw)^saturation
  Adaptation adaptation = Adaptation::LogAverage;
  AdaptationRegion lw_a_from = AdaptationRegion::View;  // view lobe, whole probe, or image
  double view_lobe_deg = 10, view_factor = 1, view_blend = 0.5;  // see AdaptationOptions
  double lw_max = 0;            // > 0: given instead of the scene's
  double lw_a = 0;              // > 0: given instead of the scene's
  double exposure = 1;          // the scene was scaled by this (--exposure): AdaptationOptions::exposure
  filters::FilterParams filter_params;  // the paper's sigmas by default
  filters::WlsParams wls;
  bool model_guide = true;      // drop guide groups that carry no information in this frame
  float guide_threshold = 0.05f;

  AdaptationOptions adaptation_options() const {
    return {adaptation, lw_a_from, view_lobe_deg, view_factor, view_blend, exposure};
  }
  // What is filtered and tone-mapped (docs/cgtmo.md, "Monte Carlo noise"):
  //   Luminance:    the beauty's luminance L; its detail L / base keeps full contrast.
  //   Illumination: I = L / (a / a_mean) where the albedo a is valid (geometry, a >= kMinAlbedo),
  //                 I = L elsewhere; the curve maps base_I, the illumination's own detail is
  //                 compressed at the curve's local slope (it is lighting: Monte Carlo noise,
  //                 shading) and a / a_mean is multiplied back at full contrast (texture).
  enum class Detail { Luminance, Illumination } detail = Detail::Luminance;
  // Display: Drago's curve, display-linear in [0, 1]. SceneLinear: no curve; the base layer's
  // range is compressed around Lw_a (pre_compression.h): its maximum to `target_stops` above the
  // scene-linear grey 0.18, its shadows into `shadow_stops` under Lw_a; Lw_a stays in place, and
  // the output is unclamped scene-linear for any display transform to finish.
  enum class Output { Display, SceneLinear } output = Output::Display;
  double target_stops = 6;
  double shadow_stops = 3.5;
};

// Albedo luminance below this is not a valid albedo (DiffCol is 0 on emitters, metals, background).
inline constexpr double kMinAlbedo = 0.02;

// What the run used, dropped and measured: `cgtmo apply --explain` prints it.
struct Explain {
  SceneStats stats;
  std::string filter;
  unsigned guide_available = 0, guide_used = 0;  // filters::GuideGroup bits
  std::vector<std::string> lines;                // used / dropped / why, in order
  double background_fraction = 0;
  std::size_t invalid_normals = 0;               // zero-length normals (filtered as background)
  double log_floor = 0;                          // luminance floor under the log10
  double filter_ms = 0;
  double exposure_scale = 1;                     // 2^EV applied to the scene's radiometric planes
  double albedo_mean = 0;                        // detail=illumination: log-average valid albedo
  double albedo_valid_fraction = 0;              // detail=illumination: share of pixels with one
  double base_headroom_stops = 0;                // output=scene-linear: base maximum over Lw_a, stops
  PreCompression pre;                            // output=scene-linear: the compression applied
};

struct LocalResult {
  std::vector<float> rgb;       // width*height*3, display-linear in [0, 1] (scene-linear: unclamped)
  std::vector<float> base_log;  // the base layer (log10 luminance), for tests and diagnostics
  Explain explain;
};

// Throws UsageError for bad options, DataError for an empty scene. `after_statistics`, when given,
// is called once the scene statistics are computed: from then on the light-group passes and the
// probe are not read again, and a caller that owns the scene may release them (peak memory).
LocalResult tone_map_local(const scene::Frame& scene, const LocalOptions& options,
                           const std::function<void()>& after_statistics = {});

// Lines for --explain (stats, guide decisions, warnings).
std::vector<std::string> describe(const Explain& e);

}  // namespace cgtmo::local
