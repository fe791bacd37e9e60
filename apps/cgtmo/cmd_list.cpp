// cgtmo list: the registry, as text or JSON.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cgtmo/cgtmo/scene_operators.h"
#include "cgtmo/operators/registry.h"
#include "cli_util.h"
#include "commands.h"

namespace cgtmo::cli {

namespace {

const char* kDescription = R"(NAME
    cgtmo list - the tone-mapping operators, their kinds and parameters

SYNOPSIS
    cgtmo list [--json]

DESCRIPTION
    Every operator of the registry with a one-line summary and citation, its kind (per-channel
    operators bake to 1D LUTs, mixing ones to 3D LUTs; scene operators, cgtmo and wls, are local
    and read the render's passes) and each parameter with its type,
    default and valid range. A default of "image ..." is computed from the input image when
    the parameter is not given. Every operator also takes --exposure (stops) in 'cgtmo apply'.
)";

const char* image_default_name(operators::ImageDefault d) {
  switch (d) {
    case operators::ImageDefault::MaxChannel: return "image max channel";
    case operators::ImageDefault::MaxLuminance: return "image max luminance";
    case operators::ImageDefault::LogAverageLuminance: return "image log-average luminance";
    case operators::ImageDefault::None: break;
  }
  return "";
}

nlohmann::json to_json(const operators::OperatorDef& op) {
  nlohmann::json j;
  j["name"] = op.name;
  j["kind"] = operators::kind_name(op.default_kind);
  j["summary"] = op.summary;
  j["citation"] = op.citation;
  j["params"] = nlohmann::json::array();
  for (const auto& p : op.params) {
    nlohmann::json q;
    q["name"] = p.name;
    q["help"] = p.help;
    switch (p.type) {
      case operators::ParamType::Number:
        q["type"] = "number";
        q["default"] = p.default_value;
        q["min"] = p.min_value;
        q["max"] = p.max_value;
        if (p.image_default != operators::ImageDefault::None) q["default_from"] = image_default_name(p.image_default);
        break;
      case operators::ParamType::Choice:
        q["type"] = "choice";
        q["default"] = p.default_text;
        q["choices"] = p.choices;
        break;
      case operators::ParamType::Text:
        q["type"] = "text";
        q["default"] = p.default_text;
        break;
    }
    j["params"].push_back(q);
  }
  return j;
}

}  // namespace

int run_list(const std::vector<std::string>& args) {
  CLI::App app{kDescription, "list"};
  style(app);
  app.footer("\nEXAMPLES\n    cgtmo list\n    cgtmo list --json | python3 -m json.tool\n");
  bool json = false;
  app.add_flag("--json", json, "machine-readable output");
  if (!parse(app, args)) return 0;

  if (json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& op : operators::registry()) all.push_back(to_json(op));
    for (const auto& op : local::scene_operators()) {
      nlohmann::json j = to_json(op);
      j["kind"] = "scene";  // local: reads the G-buffer, light groups, probe and sidecar
      all.push_back(j);
    }
    std::cout << all.dump(2) << "\n";
    return 0;
  }
  // Global operators, then the scene operators (local: they read the render's passes).
  std::vector<std::pair<const operators::OperatorDef*, const char*>> all;
  for (const auto& op : operators::registry()) all.emplace_back(&op, operators::kind_name(op.default_kind));
  for (const auto& op : local::scene_operators()) all.emplace_back(&op, "scene: reads G-buffer, light groups, probe, sidecar");
  for (const auto& [op_ptr, kind] : all) {
    const operators::OperatorDef& op = *op_ptr;
    std::cout << op.name << "  [" << kind << "]  " << op.summary << "\n";
    std::cout << "    " << op.citation << "\n";
    for (const auto& p : op.params) {
      std::cout << "    -p " << std::left << std::setw(18) << p.name;
      switch (p.type) {
        case operators::ParamType::Number:
          if (p.image_default != operators::ImageDefault::None) std::cout << "default " << image_default_name(p.image_default);
          else std::cout << "default " << p.default_value;
          std::cout << ", range [" << p.min_value << ", " << p.max_value << "]";
          break;
        case operators::ParamType::Choice: {
          std::cout << "default " << p.default_text << ", one of";
          for (const auto& c : p.choices) std::cout << " " << c;
          break;
        }
        case operators::ParamType::Text:
          std::cout << "default '" << p.default_text << "'";
          break;
      }
      std::cout << "\n        " << p.help << "\n";
    }
    std::cout << "\n";
  }
  return 0;
}

}  // namespace cgtmo::cli
