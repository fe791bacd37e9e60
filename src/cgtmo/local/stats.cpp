#include "cgtmo/local/stats.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "cgtmo/errors.h"
#include "cgtmo/local/explain_number.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::local {

Adaptation adaptation_from_name(const std::string& n) {
  if (n == "harmonic") return Adaptation::Harmonic;
  if (n == "log") return Adaptation::LogAverage;
  throw UsageError("adaptation '" + n + "' is not one of: harmonic, log");
}

const char* adaptation_name(Adaptation a) { return a == Adaptation::Harmonic ? "harmonic" : "log"; }

AdaptationRegion adaptation_region_from_name(const std::string& n) {
  if (n == "view") return AdaptationRegion::View;
  if (n == "probe") return AdaptationRegion::Sphere;
  if (n == "image") return AdaptationRegion::Image;
  throw UsageError("adaptation region '" + n + "' is not one of: view, probe, image");
}

const char* adaptation_region_name(AdaptationRegion r) {
  return r == AdaptationRegion::View ? "view" : r == AdaptationRegion::Sphere ? "probe" : "image";
}

double harmonic_mean(const float* lum, const float* w, std::size_t n) {
  double sw = 0, s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = w ? double(w[i]) : 1.0;
    sw += wi;
    s += wi / std::max(double(lum[i]), kMeanFloor);
  }
  return s > 0 ? sw / s : kMeanFloor;
}

double log_average(const float* lum, const float* w, std::size_t n) {
  double sw = 0, s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = w ? double(w[i]) : 1.0;
    sw += wi;
    s += wi * repro::log(std::max(double(lum[i]), kMeanFloor));
  }
  return sw > 0 ? repro::exp(s / sw) : kMeanFloor;
}

std::vector<float> equirect_weights(int width, int height) {
  std::vector<float> w(std::size_t(width) * height);
  for (int y = 0; y < height; ++y) {
    const double lat = M_PI / 2 - M_PI * (y + 0.5) / height;
    std::fill_n(w.begin() + std::size_t(y) * width, width, float(repro::cos(lat)));
  }
  return w;
}

std::vector<float> view_weights(int width, int height, const scene::CameraView& cam, double lobe_deg) {
  if (!cam.known || width <= 0 || height <= 0) return {};
  // The probe's centre column looks along the camera's heading unless the sidecar says otherwise.
  const double heading = std::isfinite(cam.probe_heading) ? cam.probe_heading : repro::atan2(cam.forward[1], cam.forward[0]);
  const double half_x = cam.fov_x / 2, tan_half_y = repro::tan(cam.fov_y / 2);
  const double sigma = std::max(lobe_deg, 1e-3) * M_PI / 180.0;
  std::vector<float> w(std::size_t(width) * height);
  for (int y = 0; y < height; ++y) {
    const double lat = M_PI / 2 - M_PI * (y + 0.5) / height;
    for (int x = 0; x < width; ++x) {
      // Longitude grows to the left (counter-clockwise seen from above); the centre is the heading.
      const double az = heading + M_PI - 2 * M_PI * (x + 0.5) / width;
      const double d[3] = {repro::cos(lat) * repro::cos(az), repro::cos(lat) * repro::sin(az), repro::sin(lat)};
      auto dot = [&](const double* a) { return a[0] * d[0] + a[1] * d[1] + a[2] * d[2]; };
      const double cx = dot(cam.right), cy = dot(cam.up), cz = dot(cam.forward);
      // Angles in the camera's frame: across (from forward, in the right/forward plane), and up
      // from that plane. The frame's top edge at this `across` angle is where y / z = tan(fov_y/2).
      const double across = repro::atan2(cx, cz);
      const double rise = repro::atan2(cy, repro::hypot(cx, cz));
      const double edge_y = repro::atan(tan_half_y * std::max(repro::cos(across), 0.0));
      const double dx = std::max(std::abs(across) - half_x, 0.0), dy = std::max(std::abs(rise) - edge_y, 0.0);
      const double beyond = repro::hypot(dx, dy);
      w[std::size_t(y) * width + x] = float(repro::cos(lat) * repro::exp(-0.5 * (beyond / sigma) * (beyond / sigma)));
    }
  }
  return w;
}

double blend_towards_image(double view, double image, double factor, double blend) {
  if (!(view > 0) || !(image > 0)) return view;
  const double lr = repro::log(view / image), lf = repro::log(std::max(factor, 1.0));
  if (std::abs(lr) <= lf) return view;
  const double sign = lr > 0 ? 1.0 : -1.0;
  return image * repro::exp(sign * (lf + (1.0 - blend) * (std::abs(lr) - lf)));
}

namespace {

// Lw_max from the lights (paper's buffer M), or a reason why it cannot be and what to use.
void light_statistics(const scene::Frame& s, SceneStats& st) {
  // Emitted luminance per group from the sidecar (the largest of the group's lights).
  std::map<std::string, double> sidecar_by_group;
  for (const auto& l : s.lights)
    if (std::isfinite(l.luminance) && l.luminance >= 0) {
      const std::string g = l.group.empty() ? l.name : l.group;
      sidecar_by_group[g] = std::max(sidecar_by_group.count(g) ? sidecar_by_group[g] : 0.0, l.luminance);
    }
  auto measured = [&](const scene::LightGroupPlane& g) {
    float m = 0;
    for (float v : g.luminance) m = std::max(m, v);
    return double(m);
  };
  auto emitted_of = [&](const scene::LightGroupPlane& g, GroupUse& u) {
    const auto it = sidecar_by_group.find(g.name);
    if (it != sidecar_by_group.end()) {
      u.emitted = it->second;
      u.emitted_source = "sidecar";
    } else {
      u.emitted = measured(g);
      u.emitted_source = "measured (pass maximum)";
      st.warnings.push_back("the sidecar gives no luminance for light group '" + g.name +
                            "': used the maximum of its pass (" + explain_number(u.emitted) + "), a lower bound when the emitter is not in view");
    }
  };

  // Lights that emit (a black world is listed but lights nothing).
  std::vector<const scene::LightRecord*> emitting;
  if (s.has_sidecar)
    for (const auto& l : s.lights)
      if (!(l.luminance <= 0)) emitting.push_back(&l);
  const std::size_t n_lights = emitting.size();
  const std::size_t n_groups = s.light_groups.size();
  // One light: M would hold one index everywhere; no analysis.
  if (n_lights == 1 && std::isfinite(emitting[0]->luminance)) {
    st.lw_max = emitting[0]->luminance;
    st.lw_max_source = "the only light, '" + emitting[0]->name + "' (sidecar)";
    st.light_analysis_note = "skipped: one emitting light in the sidecar";
    return;
  }
  if (n_groups == 1 && n_lights <= 1) {
    GroupUse u;
    u.name = s.light_groups[0].name;
    emitted_of(s.light_groups[0], u);
    st.lw_max = u.emitted;
    st.lw_max_source = "the only light group, '" + u.name + "' (" + u.emitted_source + ")";
    st.light_analysis_note = "skipped: one light group";
    st.groups.push_back(u);
    return;
  }
  if (n_groups == 0) {
    st.lw_max = st.image_max;
    st.lw_max_source = "image maximum";
    st.light_analysis_note = "skipped: no light-group passes";
    if (n_lights == 0)
      st.warnings.push_back(std::string(s.has_sidecar ? "the sidecar lists no lights"
                                        : "no sidecar" + (s.sidecar_absent.empty() ? "" : " (" + s.sidecar_absent + ")")) +
                            " and the render has no light-group passes: Lw_max is the image maximum (" + explain_number(st.image_max) + ")");
    else
      st.warnings.push_back("no light-group passes, so the buffer M cannot be built: Lw_max is the image maximum (" + explain_number(st.image_max) + ")");
    return;
  }
  // The buffer M: per pixel, the group with the largest contribution (none where all are 0).
  const std::size_t npx = s.pixel_count();
  std::vector<std::size_t> count(n_groups, 0);
  for (std::size_t i = 0; i < npx; ++i) {
    float best = 0;
    int arg = -1;
    for (std::size_t g = 0; g < n_groups; ++g) {
      const float v = s.light_groups[g].luminance[i];
      if (v > best) {
        best = v;
        arg = int(g);
      }
    }
    if (arg >= 0) ++count[arg];
  }
  st.light_analysis = true;
  double lw_max = 0;
  std::string from;
  int in_m = 0;
  for (std::size_t g = 0; g < n_groups; ++g) {
    GroupUse u;
    u.name = s.light_groups[g].name;
    u.pixels_in_m = count[g];
    if (count[g] == 0) {
      u.emitted_source = "not in M";
      st.groups.push_back(u);
      continue;
    }
    ++in_m;
    emitted_of(s.light_groups[g], u);
    if (u.emitted > lw_max) {
      lw_max = u.emitted;
      from = "'" + u.name + "' (" + u.emitted_source + ")";
    }
    st.groups.push_back(u);
  }
  if (in_m == 0 || !(lw_max > 0)) {
    st.lw_max = st.image_max;
    st.lw_max_source = "image maximum";
    st.light_analysis_note = "every light-group pass is black";
    st.warnings.push_back("every light-group pass is black: Lw_max is the image maximum (" + explain_number(st.image_max) + ")");
    return;
  }
  st.lw_max = lw_max;
  st.lw_max_source = "brightest light in M: " + from;
  st.light_analysis_note = std::to_string(in_m) + " of " + std::to_string(n_groups) + " light groups appear in M";
}

}  // namespace

SceneStats compute_scene_stats(const scene::Frame& s, const std::vector<float>& lum, const AdaptationOptions& ao) {
  SceneStats st;
  const Adaptation adaptation = ao.mean;
  const std::size_t n = lum.size();
  double mx = 0;
  for (float v : lum)
    if (std::isfinite(v)) mx = std::max(mx, double(v));
  st.image_max = mx;
  const double k = ao.exposure > 0 && std::isfinite(ao.exposure) ? ao.exposure : 1.0;
  if (k != 1.0 && n) {
    std::vector<float> scene_level(lum);
    for (float& v : scene_level) v = float(double(v) / k);
    st.image_harmonic = k * harmonic_mean(scene_level.data(), nullptr, n);
    st.image_log_average = k * log_average(scene_level.data(), nullptr, n);
  } else {
    st.image_harmonic = n ? harmonic_mean(lum.data(), nullptr, n) : kMeanFloor;
    st.image_log_average = n ? log_average(lum.data(), nullptr, n) : kMeanFloor;
  }

  light_statistics(s, st);

  const bool harm = adaptation == Adaptation::Harmonic;
  const std::string mean_name = harm ? "harmonic mean" : "log-average";
  bool probe_ok = false;
  std::vector<float> lit;  // 1 for probe directions that receive light, 0 for black ones
  if (s.probe.width > 0 && s.probe.height > 0 && s.probe.luminance.size() == std::size_t(s.probe.width) * s.probe.height) {
    float pmax = 0;  // probe maximum
    for (float v : s.probe.luminance) pmax = std::max(pmax, std::isfinite(v) ? v : 0.f);
    if (pmax > kMeanFloor) {
      // Directions from which no light arrives (a black world beyond the set) are no stimulus
      // to adapt to: they are left out (weight 0), instead of pulling both means to the floor.
      auto w = equirect_weights(s.probe.width, s.probe.height);
      lit.assign(w.size(), 1.f);
      double all = 0, dark = 0;
      for (std::size_t i = 0; i < w.size(); ++i) {
        all += w[i];
        if (!(s.probe.luminance[i] > kMeanFloor)) {
          dark += w[i];
          w[i] = 0.f;
          lit[i] = 0.f;
        }
      }
      st.probe_dark_fraction = dark / all;
      st.probe_harmonic = harmonic_mean(s.probe.luminance.data(), w.data(), s.probe.luminance.size());
      st.probe_log_average = log_average(s.probe.luminance.data(), w.data(), s.probe.luminance.size());
      probe_ok = true;
    } else if (ao.region != AdaptationRegion::Image) {
      st.warnings.push_back("the probe is all black: Lw_a is the image's " + mean_name);
    }
  } else if (ao.region != AdaptationRegion::Image) {
    st.warnings.push_back("no adaptation probe" + (s.probe_absent.empty() ? "" : " (" + s.probe_absent + ")") + ": Lw_a is the image's " + mean_name);
  }
  // The probe under the camera's view lobe (black directions left out, as above).
  bool view_ok = false;
  if (probe_ok) {
    std::vector<float> w = view_weights(s.probe.width, s.probe.height, s.camera, ao.lobe_deg);
    if (!w.empty()) {
      const std::vector<float> frame_only = view_weights(s.probe.width, s.probe.height, s.camera, 1e-3);
      double lobe = 0, inside = 0, kept = 0;
      for (std::size_t i = 0; i < w.size(); ++i) {
        lobe += w[i];
        inside += frame_only[i];
        w[i] *= lit[i];
        kept += w[i];
      }
      st.view_in_frame_share = lobe > 0 ? inside / lobe : 0;
      if (kept > 0) {
        st.view_harmonic = harmonic_mean(s.probe.luminance.data(), w.data(), w.size());
        st.view_log_average = log_average(s.probe.luminance.data(), w.data(), w.size());
        view_ok = true;
      }
    }
  }
  const double image_value = harm ? st.image_harmonic : st.image_log_average;
  if (ao.region == AdaptationRegion::Image || !probe_ok) {
    st.lw_a = image_value;
    st.lw_a_source = "image " + mean_name;
    if (ao.region == AdaptationRegion::Image) st.adaptation_note = "adaptation region: the image (as asked)";
  } else if (ao.region == AdaptationRegion::Sphere || !view_ok) {
    st.lw_a = harm ? st.probe_harmonic : st.probe_log_average;
    st.lw_a_source = "probe " + mean_name + " (solid-angle weighted)";
    if (ao.region == AdaptationRegion::View) {
      const std::string why = s.camera.known ? "every direction under the view lobe is black"
                                             : "the camera is unknown (no sidecar, or one without its matrix and field of view)";
      st.warnings.push_back(why + ": Lw_a from the whole probe sphere");
    }
  } else {
    const double view = harm ? st.view_harmonic : st.view_log_average;
    st.view_unblended = view;
    // The image's statistic, floor included (--exposure has scaled the image and the probe alike).
    const double image_scene = harm ? st.image_harmonic : st.image_log_average;
    st.lw_a = blend_towards_image(view, image_scene, ao.factor, ao.blend);
    st.view_blended = st.lw_a != view;
    st.lw_a_source = "probe " + mean_name + " under the view lobe (" + explain_number(ao.lobe_deg) + " deg beyond the frame)";
    const double ratio = view / image_scene, apart = ratio >= 1 ? ratio : 1 / ratio;
    if (st.view_blended) st.lw_a_source += ", blended towards the image";
    const std::string rule = st.view_blended ? "Lw_a = " + explain_number(st.lw_a) + ", keeping " + explain_number(1 - ao.blend) +
                                                   " of the log-difference beyond the factor " + explain_number(ao.factor)
                                             : "Lw_a = the view's value (within the factor " + explain_number(ao.factor) + ")";
    if (apart > kViewDisagreement)
      st.adaptation_note = "view and image disagree: the view's " + mean_name + " " + explain_number(view) + " is " + explain_number(apart) +
                           "x " + (ratio >= 1 ? "above" : "below") + " the image's " + explain_number(image_scene) +
                           " (more than " + explain_number(kViewDisagreement) + "x); " + rule;
    else
      st.adaptation_note = "view and image agree within " + explain_number(kViewDisagreement) + "x (view / image " + explain_number(ratio) + "); " + rule;
  }
  // Drago's curve needs positive statistics; a black frame gets the floor.
  if (!(st.lw_max > 0) || !std::isfinite(st.lw_max)) {
    st.warnings.push_back("Lw_max is " + explain_number(st.lw_max) + ": raised to " + explain_number(kMeanFloor));
    st.lw_max = kMeanFloor;
  }
  if (!(st.lw_a > 0) || !std::isfinite(st.lw_a)) st.lw_a = kMeanFloor;
  if (st.lw_max < st.lw_a)
    st.warnings.push_back("Lw_max (" + explain_number(st.lw_max) + ") is below Lw_a (" + explain_number(st.lw_a) +
                          "): the curve still maps Lw_max to Ld_max/100; brighter pixels clip");
  return st;
}

}  // namespace cgtmo::local
