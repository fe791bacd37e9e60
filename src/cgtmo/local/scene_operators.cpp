#include "cgtmo/local/scene_operators.h"

#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::local {

using operators::number_param;
using operators::OperatorDef;
using operators::ParamSpec;
using operators::ParamType;

namespace {

ParamSpec choice(std::string name, std::vector<std::string> choices, std::string def, std::string help) {
  ParamSpec p;
  p.name = std::move(name);
  p.type = ParamType::Choice;
  p.choices = std::move(choices);
  p.default_text = std::move(def);
  p.help = std::move(help);
  return p;
}

// Drago's parameters and the scene statistics, shared by both operators.
std::vector<ParamSpec> drago_params() {
  return {number_param("b", 0.85, 0.5, 1.0, "Drago's bias: contrast in the darks (0.7..0.9 usual)"),
          number_param("ld_max", 100, 1, 10000, "display maximum in cd/m^2 (100: Lw_max maps to 1)"),
          number_param("saturation", 1.0, 0.0, 2.0, "colour: out = Ld * (C / Lw)^saturation; 1 keeps the chromaticity"),
          choice("adaptation", {"harmonic", "log"}, kDefaultAdaptation,
                 "Lw_a from the probe: harmonic mean (the CG-TMO paper) or log-average (Drago)"),
          choice("lw_a_from", {"view", "probe", "image"}, kDefaultAdaptationRegion,
                 "Lw_a region: the probe under a lobe over the camera's frame, the whole probe sphere (the paper), or the image"),
          number_param("view_lobe", 10, 1, 180, "view lobe: Gaussian fall-off beyond the frame's edge, degrees"),
          number_param("view_factor", 1, 1, 1e6, "view and image statistics may differ by this ratio before the blend (1: always blend)"),
          number_param("view_blend", 0.5, 0, 1, "share of the log-difference beyond view_factor taken back towards the image (0.5: geometric mean)"),
          number_param("lw_max", 0, 0, 1e30, "scene maximum luminance (0: from the lights in the buffer M)"),
          number_param("lw_a", 0, 0, 1e30, "world adaptation luminance (0: from the probe)")};
}

// The output modes, shared by both operators: tone_map_local applies them after either base layer.
std::vector<ParamSpec> output_params() {
  return {choice("output", {"display", "scene-linear"}, "display",
                 "display: Drago's curve, [0, 1]; scene-linear: the base layer's range compressed around Lw_a (`stops`, `shadows`), "
                 "Lw_a kept, unclamped, for a display transform (Filmic, AgX) to finish"),
          number_param("stops", 6, 0.5, 40,
                       "output=scene-linear: where the base layer's maximum lands, in stops above scene-linear 0.18 "
                       "(Filmic and AgX reach white 6.5 stops above it)"),
          number_param("shadows", 3.5, 0, 40,
                       "output=scene-linear: the base layer's shadows are lifted into this many stops under Lw_a "
                       "(0: shadows untouched)")};
}

}  // namespace

OperatorDef cgtmo_operator() {
  OperatorDef c;
  c.name = "cgtmo";
  c.summary = "local Drago: curve on a G-buffer cross-bilateral base layer, statistics from the scene's lights and probe";
  c.citation = "Banterle, Artusi, Banterle, Scopigno, CG-TMO: a local tone mapping for computer graphics generated content, EUSIPCO 2014";
  c.scope = operators::Scope::Scene;
  c.default_kind = operators::Kind::Mixing;
  c.params = drago_params();
  c.params.insert(c.params.begin(),
                  choice("filter", filters::offered_filters("cgtmo"), "fast",
                         "base layer: " + filters::join_names(filters::offered_filters("cgtmo"), ", ") +
                             " (what each is: cgtmo apply --help, docs/cgtmo.md)"));
  c.params.push_back(number_param("sigma_s", 8, 0.5, 64, "spatial sigma of the filter, pixels (the paper: 8)"));
  c.params.push_back(number_param("sigma_pos", 8, 0.1, 1000, "position sigma in pixel footprints (the paper: sigma_s footprints)"));
  c.params.push_back(number_param("sigma_n", 0.25, 0.01, 10, "normal sigma (the paper: 0.25)"));
  c.params.push_back(number_param("sigma_albedo", 0.25, 0.01, 10, "albedo sigma (the paper: 0.25)"));
  c.params.push_back(number_param("samples", 32, 1, 4096, "poisson filter: samples per pixel"));
  c.params.push_back(choice("guide", {"auto", "all"}, "auto", "auto: drop guide groups without information in this frame"));
  c.params.push_back(choice("detail", {"luminance", "illumination"}, "luminance",
                            "what the base layer splits: luminance, or illumination (beauty / albedo; the albedo multiplied back "
                            "at full contrast, the illumination's detail compressed as lighting)"));
  for (auto& p : output_params()) c.params.push_back(std::move(p));
  return c;
}

OperatorDef wls_operator() {
  OperatorDef w;
  w.name = "wls";
  w.summary = "local Drago on a weighted-least-squares base layer (the CG-TMO paper's WLS-TMO baseline)";
  w.citation = "Farbman, Fattal, Lischinski, Szeliski, Edge-preserving decompositions for multi-scale tone and detail manipulation, SIGGRAPH 2008";
  w.scope = operators::Scope::Scene;
  w.default_kind = operators::Kind::Mixing;
  w.params = drago_params();
  w.params.push_back(number_param("alpha", 1.2, 0.1, 4, "WLS gradient sensitivity (the paper: 1.2)"));
  w.params.push_back(number_param("lambda", 0.125, 0, 100, "WLS smoothness (the paper: 0.125)"));
  for (auto& p : output_params()) w.params.push_back(std::move(p));
  return w;
}

const OperatorDef& find_scene_operator(const std::string& name) {
  const OperatorDef& op = operators::find_operator(name);
  if (op.scope == operators::Scope::Scene) return op;
  std::string names;
  for (const auto& s : operators::operators_of(operators::Scope::Scene)) names += (names.empty() ? "" : ", ") + s.name;
  throw UsageError("'" + name + "' is not a scene operator (scene operators: " + names + ")");
}

LocalOptions options_from(const OperatorDef& op, const operators::ParamValues& v) {
  LocalOptions o;
  o.b = v.number("b");
  o.ld_max = v.number("ld_max");
  o.saturation = v.number("saturation");
  o.adaptation = adaptation_from_name(v.text("adaptation"));
  o.lw_a_from = adaptation_region_from_name(v.text("lw_a_from"));
  o.view_lobe_deg = v.number("view_lobe");
  o.view_factor = v.number("view_factor");
  o.view_blend = v.number("view_blend");
  o.lw_max = v.number("lw_max");
  o.lw_a = v.number("lw_a");
  if (op.name == "wls") {
    o.filter = "wls";
    o.wls.alpha = v.number("alpha");
    o.wls.lambda = v.number("lambda");
  } else {
    o.filter = v.text("filter");
    o.filter_params.sigma_spatial_px = float(v.number("sigma_s"));
    o.filter_params.sigma_pos_footprints = float(v.number("sigma_pos"));
    o.filter_params.sigma_normal = float(v.number("sigma_n"));
    o.filter_params.sigma_albedo = float(v.number("sigma_albedo"));
    o.filter_params.poisson_samples = int(v.number("samples"));
    o.model_guide = v.text("guide") == "auto";
    o.detail = v.text("detail") == "illumination" ? LocalOptions::Detail::Illumination : LocalOptions::Detail::Luminance;
  }
  o.output = v.text("output") == "scene-linear" ? LocalOptions::Output::SceneLinear : LocalOptions::Output::Display;
  o.target_stops = v.number("stops");
  o.shadow_stops = v.number("shadows");
  return o;
}

bool needs_gbuffer(const LocalOptions& o) { return filters::find_filter(o.filter).needs_gbuffer; }

}  // namespace cgtmo::local
