#include "cgtmo/cgtmo/stats.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "cgtmo/errors.h"

namespace cgtmo::local {

Adaptation adaptation_from_name(const std::string& n) {
  if (n == "harmonic") return Adaptation::Harmonic;
  if (n == "log") return Adaptation::LogAverage;
  throw UsageError("adaptation '" + n + "' is not one of: harmonic, log");
}

const char* adaptation_name(Adaptation a) { return a == Adaptation::Harmonic ? "harmonic" : "log"; }

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
    s += wi * std::log(std::max(double(lum[i]), kMeanFloor));
  }
  return sw > 0 ? std::exp(s / sw) : kMeanFloor;
}

std::vector<float> equirect_weights(int width, int height) {
  std::vector<float> w(std::size_t(width) * height);
  for (int y = 0; y < height; ++y) {
    const double lat = M_PI / 2 - M_PI * (y + 0.5) / height;
    std::fill_n(w.begin() + std::size_t(y) * width, width, float(std::cos(lat)));
  }
  return w;
}

namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(5);
  o << v;
  return o.str();
}

// Lw_max from the lights (paper's buffer M), or a reason why it cannot be and what to use.
void light_statistics(const SceneData& s, SceneStats& st) {
  // Emitted luminance per group from the sidecar (the largest of the group's lights).
  std::map<std::string, double> sidecar_by_group;
  for (const auto& l : s.lights)
    if (std::isfinite(l.luminance) && l.luminance >= 0) {
      const std::string g = l.group.empty() ? l.name : l.group;
      sidecar_by_group[g] = std::max(sidecar_by_group.count(g) ? sidecar_by_group[g] : 0.0, l.luminance);
    }
  auto measured = [&](const LightGroupPass& g) {
    float m = 0;
    for (float v : g.luminance) m = std::max(m, v);
    return double(m);
  };
  auto emitted_of = [&](const LightGroupPass& g, GroupUse& u) {
    const auto it = sidecar_by_group.find(g.name);
    if (it != sidecar_by_group.end()) {
      u.emitted = it->second;
      u.emitted_source = "sidecar";
    } else {
      u.emitted = measured(g);
      u.emitted_source = "measured (pass maximum)";
      st.warnings.push_back("the sidecar gives no luminance for light group '" + g.name +
                            "': used the maximum of its pass (" + fmt(u.emitted) + "), a lower bound when the emitter is not in view");
    }
  };

  // Lights that emit (a black world is listed but lights nothing).
  std::vector<const LightRecord*> emitting;
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
                            " and the render has no light-group passes: Lw_max is the image maximum (" + fmt(st.image_max) + ")");
    else
      st.warnings.push_back("no light-group passes, so the buffer M cannot be built: Lw_max is the image maximum (" + fmt(st.image_max) + ")");
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
    st.warnings.push_back("every light-group pass is black: Lw_max is the image maximum (" + fmt(st.image_max) + ")");
    return;
  }
  st.lw_max = lw_max;
  st.lw_max_source = "brightest light in M: " + from;
  st.light_analysis_note = std::to_string(in_m) + " of " + std::to_string(n_groups) + " light groups appear in M";
}

}  // namespace

SceneStats compute_scene_stats(const SceneData& s, const std::vector<float>& lum, Adaptation adaptation) {
  SceneStats st;
  const std::size_t n = lum.size();
  double mx = 0;
  for (float v : lum)
    if (std::isfinite(v)) mx = std::max(mx, double(v));
  st.image_max = mx;
  st.image_harmonic = n ? harmonic_mean(lum.data(), nullptr, n) : kMeanFloor;
  st.image_log_average = n ? log_average(lum.data(), nullptr, n) : kMeanFloor;

  light_statistics(s, st);

  bool probe_ok = false;
  if (s.probe.width > 0 && s.probe.height > 0 && s.probe.luminance.size() == std::size_t(s.probe.width) * s.probe.height) {
    float pmax = 0;  // probe maximum
    for (float v : s.probe.luminance) pmax = std::max(pmax, std::isfinite(v) ? v : 0.f);
    if (pmax > kMeanFloor) {
      // Directions from which no light arrives (a black world beyond the set) are no stimulus
      // to adapt to: they are left out (weight 0), instead of pulling both means to the floor.
      auto w = equirect_weights(s.probe.width, s.probe.height);
      double all = 0, dark = 0;
      for (std::size_t i = 0; i < w.size(); ++i) {
        all += w[i];
        if (!(s.probe.luminance[i] > kMeanFloor)) {
          dark += w[i];
          w[i] = 0.f;
        }
      }
      st.probe_dark_fraction = dark / all;
      st.probe_harmonic = harmonic_mean(s.probe.luminance.data(), w.data(), s.probe.luminance.size());
      st.probe_log_average = log_average(s.probe.luminance.data(), w.data(), s.probe.luminance.size());
      probe_ok = true;
    } else {
      st.warnings.push_back("the probe is all black: Lw_a is the image's " + std::string(adaptation == Adaptation::Harmonic ? "harmonic mean" : "log-average"));
    }
  } else {
    st.warnings.push_back("no adaptation probe" + (s.probe_absent.empty() ? "" : " (" + s.probe_absent + ")") + ": Lw_a is the image's " + std::string(adaptation == Adaptation::Harmonic ? "harmonic mean" : "log-average"));
  }
  const bool harm = adaptation == Adaptation::Harmonic;
  if (probe_ok) {
    st.lw_a = harm ? st.probe_harmonic : st.probe_log_average;
    st.lw_a_source = std::string("probe ") + (harm ? "harmonic mean" : "log-average") + " (solid-angle weighted)";
  } else {
    st.lw_a = harm ? st.image_harmonic : st.image_log_average;
    st.lw_a_source = std::string("image ") + (harm ? "harmonic mean" : "log-average");
  }
  // Drago's curve needs positive statistics; a black frame gets the floor.
  if (!(st.lw_max > 0) || !std::isfinite(st.lw_max)) {
    st.warnings.push_back("Lw_max is " + fmt(st.lw_max) + ": raised to " + fmt(kMeanFloor));
    st.lw_max = kMeanFloor;
  }
  if (!(st.lw_a > 0) || !std::isfinite(st.lw_a)) st.lw_a = kMeanFloor;
  if (st.lw_max < st.lw_a)
    st.warnings.push_back("Lw_max (" + fmt(st.lw_max) + ") is below Lw_a (" + fmt(st.lw_a) +
                          "): the curve still maps Lw_max to Ld_max/100; brighter pixels clip");
  return st;
}

}  // namespace cgtmo::local
