#pragma once
// Picks, per operator, the cheapest LUT design whose audited error meets a budget: 1D where the
// operator is per-channel, then the smallest size, then the narrowest shaper.
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "cgtmo/bake/audit.h"
#include "cgtmo/bake/lut.h"
#include "cgtmo/operators/operator.h"

namespace cgtmo::bake {

// Image-dependent defaults (reinhard-ext's white, drago's lw_max and lw_a, ...) cannot follow an
// image inside a LUT: the shipped config bakes them for this reference scene, a render whose
// brightest value and luminance is 16 (4 stops over diffuse white) with a log-average of 0.18.
operators::ImageStats reference_scene_stats();

// The accuracy targets: per-channel curves 0.1 code value, operators that mix channels 1.
double default_budget_cv(operators::Kind k);

// An operator with its parameters bound, as the baker sees it.
struct BakeSubject {
  const operators::OperatorDef* def = nullptr;
  std::map<std::string, std::string> given;   // user-given key=value
  operators::ParamValues params;              // resolved
  std::unique_ptr<operators::Evaluator> exact;      // clamped: the audit's reference
  std::unique_ptr<operators::Evaluator> unclamped;  // what 3D LUTs sample
  std::string params_text() const;            // "white=16 b=0.85"
};

BakeSubject make_subject(const operators::OperatorDef& def, const std::map<std::string, std::string>& given,
                         const operators::ImageStats& stats);

struct Choice {
  BakedLut lut;
  AuditResult audit;
  bool met = false;  // false: no candidate met the budget; `lut` is the most accurate one tried
  int candidates_tried = 0;
};

// The sRGB display encoding of the built-in config, appended to a view for the audit.
OCIO::ConstTransformRcPtr srgb_display_encoding();

// A CPU processor: scene-linear -> sRGB-encoded through `lut` (inline LUT).
OCIO::ConstCPUProcessorRcPtr encoded_processor(const BakedLut& lut);

using Progress = std::function<void(const std::string&)>;

Choice choose_representation(const BakeSubject& subject, double budget_cv, const Progress& progress = {});

// The largest 3D grid the search tries: 65^3 (.spi3d about 10 MB, docs/platform.md) keeps files < 20 MB.
inline constexpr int kMax3DSize = 65;

}  // namespace cgtmo::bake
