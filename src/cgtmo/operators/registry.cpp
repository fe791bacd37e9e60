#include "cgtmo/operators/registry.h"

#include "cgtmo/errors.h"

namespace cgtmo::operators {

// Defined one per file in this folder.
OperatorDef linear_operator();
OperatorDef reinhard_operator();
OperatorDef reinhard_ext_operator();
OperatorDef reinhard_lum_operator();
OperatorDef reinhard_jodie_operator();
OperatorDef hable_operator();
OperatorDef hable_piecewise_operator();
OperatorDef aces_hill_operator();
OperatorDef aces_narkowicz_operator();
OperatorDef uchimura_operator();
OperatorDef lottes_operator();
OperatorDef unreal_operator();
OperatorDef pbr_neutral_operator();
OperatorDef agx_operator();
OperatorDef drago_operator();
OperatorDef camera_operator();

const std::vector<OperatorDef>& registry() {
  static const std::vector<OperatorDef> all = {
      linear_operator(),        reinhard_operator(),        reinhard_ext_operator(),
      reinhard_lum_operator(),  reinhard_jodie_operator(),  hable_operator(),
      hable_piecewise_operator(), aces_hill_operator(),     aces_narkowicz_operator(),
      uchimura_operator(),      lottes_operator(),          unreal_operator(),
      pbr_neutral_operator(),   agx_operator(),             drago_operator(),
      camera_operator(),
  };
  return all;
}

const OperatorDef& find_operator(const std::string& name) {
  for (const auto& op : registry())
    if (op.name == name) return op;
  std::string names;
  for (const auto& op : registry()) names += (names.empty() ? "" : ", ") + op.name;
  throw UsageError("unknown operator '" + name + "' (known: " + names + ")");
}

}  // namespace cgtmo::operators
