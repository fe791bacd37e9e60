// cgtmo list: the registry, as text or JSON.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

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

    --json prints the same description the Python module's cgtmo.operators() returns: per
    operator name, scope (pixel or scene), kind (per-channel or mixing), summary, citation and
    params (name, type, default, help; min, max and default_from for numbers; choices).
)";

// The text form of a parameter's image default: "image max channel" for max_channel.
std::string image_default_text(operators::ImageDefault d) {
  std::string name = operators::image_default_name(d);
  for (auto& c : name)
    if (c == '_') c = ' ';
  return "image " + name;
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
    // The library's one description, as the Python module and the add-on show it.
    std::cout << operators::describe_registry().dump(2) << "\n";
    return 0;
  }
  // Pixel operators, then the scene operators (local: they read the render's passes).
  for (const auto& op : operators::registry()) {
    const char* kind = op.scope == operators::Scope::Scene ? "scene: reads G-buffer, light groups, probe, sidecar"
                                                           : operators::kind_name(op.default_kind);
    std::cout << op.name << "  [" << kind << "]  " << op.summary << "\n";
    std::cout << "    " << op.citation << "\n";
    for (const auto& p : op.params) {
      std::cout << "    -p " << std::left << std::setw(18) << p.name;
      switch (p.type) {
        case operators::ParamType::Number:
          if (p.image_default != operators::ImageDefault::None) std::cout << "default " << image_default_text(p.image_default);
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
