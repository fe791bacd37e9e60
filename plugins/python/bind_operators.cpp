// The registry as Python data: what the Blender panel and scripts iterate.
#include <nlohmann/json.hpp>

#include "bindings.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::python {

namespace {

// JSON text to Python data (dicts, lists, str, float, bool, None) through the json module.
py::object from_json(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

}  // namespace

py::object operator_dict(const operators::OperatorDef& op) { return from_json(operators::describe(op)); }

py::dict params_dict(const operators::ParamValues& v) {
  py::dict d;
  for (const auto& [k, x] : v.numbers()) d[py::str(k)] = x;
  for (const auto& [k, x] : v.texts()) d[py::str(k)] = x;
  return d;
}

void bind_operators(py::module_& m) {
  m.def(
      "operators",
      [] {
        return from_json(operators::describe_registry());
      },
      "Every operator of the registry as a dict, exactly as `cgtmo list --json` prints it: name, scope "
      "('pixel': per pixel; 'scene': reads the render's passes, light groups, probe and sidecar, see "
      "apply_scene), kind ('per-channel' or 'mixing'), summary, citation, params (each a dict: name, type, "
      "default, help; min, max and, when the default is an image statistic, default_from for numbers; "
      "choices).");
  m.def(
      "operator", [](const std::string& name) { return operator_dict(operators::find_operator(name)); }, py::arg("name"),
      "One operator's dict (ValueError naming the known operators when unknown).");
  m.def(
      "resolve_params",
      [](const std::string& name, const py::object& params) {
        // Image-derived defaults stay unresolved here: they need an image (see apply()).
        const auto& op = operators::find_operator(name);
        const auto given = params_from_dict(params);
        const operators::ImageStats placeholder{1.0, 1.0, 1.0};
        return params_dict(operators::resolve_params(op, given, &placeholder));
      },
      py::arg("op"), py::arg("params") = py::none(),
      "Validates parameters against the registry (ValueError when wrong) and returns them with the "
      "fixed defaults filled in (image-derived defaults show a placeholder of 1).");
}

}  // namespace cgtmo::python
