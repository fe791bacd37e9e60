#include "cgtmo/local/local_drago.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/local/filter_input.h"
#include "cgtmo/local/pre_compression.h"
#include "cgtmo/operators/drago_curve.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/local/explain_number.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::local {

namespace {

float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

}  // namespace

LocalResult tone_map_local(const scene::Frame& s, const LocalOptions& opt, const std::function<void()>& after_statistics) {
  if (s.width <= 0 || s.height <= 0 || (s.channels != 3 && s.channels != 4) ||
      s.beauty.size() != s.pixel_count() * std::size_t(s.channels)) throw DataError("cgtmo: empty or inconsistent frame");
  const filters::FilterEntry& filter = filters::find_filter(opt.filter);  // UsageError when unknown
  const bool is_wls = filter.function == nullptr;  // wls: its own solver (wls.h)
  const filters::FilterFunction cross = filter.function;
  const std::size_t n = s.pixel_count();
  LocalResult r;
  Explain& ex = r.explain;
  ex.filter = opt.filter;

  // Luminance of the (sanitised) beauty.
  std::vector<float> lum = beauty_luminance(s);

  ex.stats = compute_scene_stats(s, lum, opt.adaptation_options());
  if (after_statistics) after_statistics();
  SceneStats& st = ex.stats;
  if (opt.lw_max > 0) {
    st.lw_max = opt.lw_max;
    st.lw_max_source = "given (lw_max)";
  }
  if (opt.lw_a > 0) {
    st.lw_a = opt.lw_a;
    st.lw_a_source = "given (lw_a)";
  }

  // detail=illumination: per pixel the albedo factor a / a_mean that the illumination leaves out
  // and the output multiplies back (1 where the albedo is not valid). Normalising by the frame's
  // log-average valid albedo keeps the illumination at the luminance's level, so the scene
  // statistics (of luminance) still describe it.
  const bool illumination = opt.detail == LocalOptions::Detail::Illumination;
  std::vector<float> albedo_factor;
  if (illumination) {
    albedo_factor.assign(n, 0.f);  // the valid albedo's luminance, 0 where not valid
    if (s.albedo.size() == n * 3) {
      double log_sum = 0;
      std::size_t valid = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const bool geo = !is_background(s, i);
        const float* a = &s.albedo[3 * i];
        const double ay = color::luminance(a[0], a[1], a[2]);
        if (!geo || !(ay >= kMinAlbedo) || !std::isfinite(ay)) continue;
        albedo_factor[i] = float(ay);
        log_sum += repro::log(ay);
        ++valid;
      }
      ex.albedo_valid_fraction = double(valid) / double(n);
      ex.albedo_mean = valid ? repro::exp(log_sum / double(valid)) : 1.0;
      for (float& f : albedo_factor) f = f > 0.f ? float(f / ex.albedo_mean) : 1.f;
      ex.lines.push_back("detail: illumination = luminance / (albedo / " + explain_number(ex.albedo_mean) + ") on " +
                         explain_number(100.0 * ex.albedo_valid_fraction) + "% of the pixels (valid albedo), luminance elsewhere");
    } else {
      albedo_factor.assign(n, 1.f);
      st.warnings.push_back("detail=illumination without a DiffCol (albedo) pass: the illumination is the luminance");
    }
  }

  // The signal: floored log10 luminance (or illumination).
  ex.log_floor = log_floor_of(st.lw_a);
  std::vector<float> log_lum(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = illumination ? double(lum[i]) / double(albedo_factor[i]) : double(lum[i]);
    log_lum[i] = floored_log10(v, ex.log_floor);
  }
  // The linear luminance is recomputed from the beauty at the end (the same expression): holding
  // it through the filter would add one float plane to the peak memory.
  std::vector<float>().swap(lum);

  // Mask, normals and footprint as every user of the filters gets them (filter_input.h).
  FilterInput fi = build_filter_input(s, std::move(log_lum));
  const filters::GuidedInput& in = fi.input;
  const unsigned available = fi.available;
  ex.background_fraction = fi.background_fraction;
  ex.invalid_normals = fi.invalid_normals;
  for (auto& line : fi.lines) ex.lines.push_back(std::move(line));
  filters::FilterParams fp = opt.filter_params;
  ex.guide_available = available;
  const unsigned missing = filters::kGuideAll & ~available;
  if (missing && filter.needs_gbuffer) {
    ex.lines.push_back("guide: " + filters::describe_groups(missing) + " missing from the render: not used");
    // Without any G-buffer pass the base layer is a plain spatial blur, not CG-TMO's: say so.
    if (!available)
      st.warnings.push_back("no Position, Normal or DiffCol pass: the base layer is a spatial blur of the luminance, "
                            "not guided by the G-buffer");
  }

  // Model only what the frame needs: drop guide groups that carry no information.
  fp.groups = available & opt.filter_params.groups;
  if (!filter.needs_gbuffer) {
    fp.groups = 0;
    ex.lines.push_back("guide: none (" + opt.filter + " filters luminance alone)");
  } else if (opt.model_guide && fp.groups) {
    const filters::GuideAnalysis ga = filters::analyze_guide(in, fp, opt.guide_threshold);
    const unsigned dropped = fp.groups & ~ga.informative;
    fp.groups &= ga.informative;
    std::istringstream lines(ga.explain);
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) ex.lines.push_back("guide: " + line);
    if (dropped) ex.lines.push_back("guide: dropped " + filters::describe_groups(dropped) + " (no information in this frame)");
  }
  ex.guide_used = fp.groups;
  ex.lines.push_back("guide: filtering with " + filters::describe_groups(fp.groups));

  r.base_log.resize(n);
  const auto t0 = std::chrono::steady_clock::now();
  if (is_wls) {
    filters::WlsReport rep;
    filters::wls_filter(in, opt.wls, r.base_log.data(), &rep);
    ex.lines.push_back("wls: " + std::to_string(rep.unknowns) + " unknowns, " + std::to_string(rep.iterations) +
                       " CG iterations, residual " + explain_number(rep.residual));
  } else {
    cross(in, fp, r.base_log.data());
  }
  ex.filter_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  // The filter's inputs go before the output is allocated (peak memory); what the last loop needs
  // of them is recomputed there.
  fi.release();

  // output=scene-linear: the base layer's range compressed around Lw_a (pre_compression.h); the
  // detail is kept: L' = L 2^(u' - u).
  const bool scene_linear = opt.output == LocalOptions::Output::SceneLinear;
  PreCompression pre;
  if (scene_linear) {
    float top = -std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(r.base_log[i])) top = std::max(top, r.base_log[i]);
    const double headroom = std::isfinite(top) ? (double(top) - repro::log10(st.lw_a)) / repro::log10(2.0) : 0.0;
    ex.base_headroom_stops = headroom;
    pre = plan_pre_compression(headroom, st.lw_a, opt.target_stops, opt.shadow_stops);
    ex.pre = pre;
    ex.lines.push_back("output: scene-linear; the base reaches " + explain_number(headroom) + " stops above Lw_a = " + explain_number(st.lw_a) +
                       ", target " + explain_number(pre.target) + " (" + explain_number(opt.target_stops) + " above " + explain_number(kSceneLinearGrey) + ")" +
                       (pre.k_high > 0 ? ": shoulder v / (1 + " + explain_number(pre.k_high) + " v) from " + explain_number(pre.knee_high) + " stops above Lw_a"
                                       : ": within the target, unchanged"));
    ex.lines.push_back(pre.k_low > 0 ? "output: shadows more than " + explain_number(pre.knee_low) + " stops under Lw_a lifted into " +
                                           explain_number(opt.shadow_stops) + " stops under it (w / (1 + " + explain_number(pre.k_low) + " w))"
                                     : "output: shadows unchanged (shadows=0)");
  }

  // Ld = TC(base) * L / base, then colour from Ld / L.
  const operators::DragoCurve tc = operators::make_drago(opt.b, opt.ld_max, st.lw_max, st.lw_a);
  // The curve's slope in log-log coordinates at x: how much it compresses variations around x.
  auto log_slope = [&tc](double x) {
    constexpr double h = 1.05;
    const double up = tc(x * h), down = tc(x / h);
    if (!(up > 0) || !(down > 0)) return 1.0;
    return std::clamp(repro::log(up / down) / (2 * repro::log(h)), 0.0, 1.0);
  };
  r.rgb.resize(n * 3);
  const double sat = opt.saturation;
  const double inv_lw_a = 1.0 / st.lw_a;
  parallel_rows(int64_t(n), [&](int64_t b, int64_t e) {
    for (int64_t i = b; i < e; ++i) {
      float* o = &r.rgb[3 * i];
      const float* c = s.rgb_at(std::size_t(i));
      const float y = color::luminance(c[0], c[1], c[2]);  // as computed at the top
      const double l = std::isfinite(y) ? std::max(y, 0.f) : 0.f;
      const double m = illumination ? double(albedo_factor[i]) : 1.0;
      double bl = r.base_log[i];
      if (!std::isfinite(bl)) bl = repro::log10(std::max(l / m, ex.log_floor));  // never expected; keeps the output defined
      const double base = repro::pow(10.0, bl);
      double ld = 0.0;
      if (l > 0) {
        if (scene_linear) {
          ld = l * repro::exp2(pre.log2_gain(repro::log2(base * inv_lw_a)));
        } else if (illumination) {
          ld = m * tc(base) * repro::pow((l / m) / base, log_slope(base));
        } else {
          ld = tc(base) * (l / base);
        }
      }
      if (!(l > 0) || !std::isfinite(ld)) {
        o[0] = o[1] = o[2] = 0.f;
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        const double ratio = std::max(double(c[k]), 0.0) / l;
        const float v = float(ld * (sat == 1.0 ? ratio : repro::pow(ratio, sat)));
        // Scene-linear: the toe lifts a lone highlight in a dark region with its base; never past the
        // ceiling the reader holds inputs to (a half-float EXR's largest value).
        o[k] = scene_linear ? std::min(v, scene::kMaxInputValue) : clamp01(v);
      }
    }
  });
  return r;
}

std::vector<std::string> describe(const Explain& e) {
  std::vector<std::string> out;
  const SceneStats& st = e.stats;
  out.push_back("filter: " + e.filter + " (" + explain_number(e.filter_ms) + " ms)");
  if (e.exposure_scale != 1)
    out.push_back("exposure: x" + explain_number(e.exposure_scale) + " (" + explain_number(repro::log2(e.exposure_scale)) +
                  " EV) on the beauty, the light groups, the sidecar's light luminances and the probe: the statistics below are the exposed scene's");
  out.push_back("Lw_max = " + explain_number(st.lw_max) + "  from " + st.lw_max_source + "; image maximum " + explain_number(st.image_max) +
                (st.image_max > 0 ? " (ratio " + explain_number(st.lw_max / st.image_max) + ")" : ""));
  out.push_back("light analysis: " + (st.light_analysis_note.empty() ? std::string("none") : st.light_analysis_note));
  for (const auto& g : st.groups)
    out.push_back("  group '" + g.name + "': " + std::to_string(g.pixels_in_m) + " px in M" +
                  (g.emitted_source == "not in M" ? "" : ", emitted " + explain_number(g.emitted) + " (" + g.emitted_source + ")"));
  out.push_back("Lw_a = " + explain_number(st.lw_a) + "  from " + st.lw_a_source);
  if (st.probe_harmonic > 0)
    out.push_back("  probe: harmonic mean " + explain_number(st.probe_harmonic) + ", log-average " + explain_number(st.probe_log_average) +
                  " over its lit directions (" + explain_number(100.0 * st.probe_dark_fraction) + "% of the sphere black, left out)");
  if (st.view_harmonic > 0)
    out.push_back("  view lobe: harmonic mean " + explain_number(st.view_harmonic) + ", log-average " + explain_number(st.view_log_average) +
                  " (" + explain_number(100.0 * st.view_in_frame_share) + "% of the lobe's weight inside the frame)");
  out.push_back("  image: harmonic mean " + explain_number(st.image_harmonic) + ", log-average " + explain_number(st.image_log_average));
  if (!st.adaptation_note.empty()) out.push_back("  " + st.adaptation_note);
  out.push_back("background: " + explain_number(100.0 * e.background_fraction) + "% of the pixels (global curve there)");
  out.push_back("log10 floor: luminance below " + explain_number(e.log_floor) + " (1e-4 Lw_a) counts as it");
  for (const auto& l : e.lines) out.push_back(l);
  for (const auto& w : st.warnings) out.push_back("warning: " + w);
  return out;
}

}  // namespace cgtmo::local
