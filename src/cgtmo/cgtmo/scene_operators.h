#pragma once
// The operators that need the scene, not just a pixel: CG-TMO and the WLS-TMO baseline. They use
// the registry's data types (name, summary, citation, typed parameters with ranges) so that
// parameters are validated the same way, but they are listed apart from operators::registry():
// everything that iterates that registry (LUT baking, OCIO config, per-pixel benchmarks and tests)
// assumes a per-pixel Evaluator, which a local operator cannot be (`make` is null here).
#include <string>
#include <vector>

#include "cgtmo/cgtmo/local_drago.h"
#include "cgtmo/operators/operator.h"

namespace cgtmo::local {

const std::vector<operators::OperatorDef>& scene_operators();
// nullptr when `name` is not a scene operator.
const operators::OperatorDef* find_scene_operator(const std::string& name);
// The options a resolved parameter set describes.
LocalOptions options_from(const operators::OperatorDef& op, const operators::ParamValues& v);
// Which passes the operator reads beyond the beauty.
bool needs_gbuffer(const LocalOptions& o);

// The default Lw_a statistic, chosen by TMQI on the committed scenes (docs/cgtmo.md).
inline constexpr const char* kDefaultAdaptation = "log";
// The default region Lw_a is measured over, chosen by TMQI on the committed scenes (docs/cgtmo.md).
inline constexpr const char* kDefaultAdaptationRegion = "view";

}  // namespace cgtmo::local
