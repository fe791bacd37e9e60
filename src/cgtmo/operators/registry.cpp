#include "cgtmo/operators/registry.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "cgtmo/errors.h"
#include "cgtmo/util/text.h"

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

}  // namespace cgtmo::operators

namespace cgtmo::local {
// The scene operators are defined beside their evaluation (cgtmo/scene_operators.cpp).
operators::OperatorDef cgtmo_operator();
operators::OperatorDef wls_operator();
}  // namespace cgtmo::local

namespace cgtmo::operators {

const std::vector<OperatorDef>& registry() {
  static const std::vector<OperatorDef> all = [] {
    std::vector<OperatorDef> v = {
        linear_operator(),        reinhard_operator(),        reinhard_ext_operator(),
        reinhard_lum_operator(),  reinhard_jodie_operator(),  hable_operator(),
        hable_piecewise_operator(), aces_hill_operator(),     aces_narkowicz_operator(),
        uchimura_operator(),      lottes_operator(),          unreal_operator(),
        pbr_neutral_operator(),   agx_operator(),             drago_operator(),
        camera_operator(),
        local::cgtmo_operator(),  local::wls_operator(),
    };
    // Pixel scope first, so that operators_of() is a contiguous run.
    std::stable_partition(v.begin(), v.end(), [](const OperatorDef& op) { return op.scope == Scope::Pixel; });
    return v;
  }();
  return all;
}

OperatorRange operators_of(Scope scope) {
  const auto& all = registry();
  const OperatorDef* first = all.data();
  const OperatorDef* last = all.data() + all.size();
  const OperatorDef* split =
      std::partition_point(first, last, [](const OperatorDef& op) { return op.scope == Scope::Pixel; });
  return scope == Scope::Pixel ? OperatorRange(first, split) : OperatorRange(split, last);
}

const OperatorDef& find_operator(const std::string& name) {
  for (const auto& op : registry())
    if (op.name == name) return op;
  std::string names;
  std::vector<std::string> known;
  for (const auto& op : registry()) {
    names += (names.empty() ? "" : ", ") + op.name;
    known.push_back(op.name);
  }
  throw UsageError("unknown operator '" + name + "'" + did_you_mean(name, known) + " (known: " + names + ")");
}

nlohmann::json describe(const OperatorDef& op) {
  nlohmann::json j;
  j["name"] = op.name;
  j["scope"] = scope_name(op.scope);
  j["kind"] = kind_name(op.default_kind);
  j["summary"] = op.summary;
  j["citation"] = op.citation;
  j["params"] = nlohmann::json::array();
  for (const auto& p : op.params) {
    nlohmann::json q;
    q["name"] = p.name;
    q["help"] = p.help;
    switch (p.type) {
      case ParamType::Number:
        q["type"] = "number";
        q["default"] = p.default_value;
        q["min"] = p.min_value;
        q["max"] = p.max_value;
        // Set when the default is a statistic of the image (the fixed default is then unused).
        if (p.image_default != ImageDefault::None) q["default_from"] = image_default_name(p.image_default);
        break;
      case ParamType::Choice:
        q["type"] = "choice";
        q["default"] = p.default_text;
        q["choices"] = p.choices;
        break;
      case ParamType::Text:
        q["type"] = "text";
        q["default"] = p.default_text;
        break;
    }
    j["params"].push_back(q);
  }
  return j;
}

nlohmann::json describe_registry() {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& op : registry()) all.push_back(describe(op));
  return all;
}

}  // namespace cgtmo::operators
