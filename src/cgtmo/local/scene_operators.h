#pragma once
// The operators that need the scene, not just a pixel: CG-TMO and the WLS-TMO baseline. They are
// entries of operators::registry() with Scope::Scene (defined here, beside their evaluation:
// cgtmo_operator(), wls_operator()); `make` is null, as a local operator has no per-pixel form.
// Here: how their resolved parameters become the local pipeline's options.
#include <string>
#include <vector>

#include "cgtmo/local/local_drago.h"
#include "cgtmo/operators/operator.h"

namespace cgtmo::local {

// The registry entry `name` when it has Scope::Scene; UsageError otherwise (naming the scene
// operators when `name` is a pixel operator or unknown).
const operators::OperatorDef& find_scene_operator(const std::string& name);
// The options a resolved parameter set describes.
LocalOptions options_from(const operators::OperatorDef& op, const operators::ParamValues& v);
// Which passes the operator reads beyond the beauty.
bool needs_gbuffer(const LocalOptions& o);

// The default Lw_a statistic, chosen by TMQI on the committed scenes (docs/cgtmo.md).
inline constexpr const char* kDefaultAdaptation = "log";
// The default region Lw_a is measured over, chosen by TMQI on the committed scenes (docs/cgtmo.md).
inline constexpr const char* kDefaultAdaptationRegion = "view";

}  // namespace cgtmo::local
