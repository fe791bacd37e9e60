// The registry as Python data: what the Blender panel and scripts iterate.
#include "bindings.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::python {

namespace {

const char* image_default_name(operators::ImageDefault d) {
  switch (d) {
    case operators::ImageDefault::MaxChannel: return "max_channel";
    case operators::ImageDefault::MaxLuminance: return "max_luminance";
    case operators::ImageDefault::LogAverageLuminance: return "log_average_luminance";
    case operators::ImageDefault::None: break;
  }
  return "";
}

py::dict param_dict(const operators::ParamSpec& p) {
  py::dict d;
  d["name"] = p.name;
  d["help"] = p.help;
  switch (p.type) {
    case operators::ParamType::Number:
      d["type"] = "number";
      d["default"] = p.default_value;
      d["min"] = p.min_value;
      d["max"] = p.max_value;
      break;
    case operators::ParamType::Choice:
      d["type"] = "choice";
      d["default"] = p.default_text;
      d["choices"] = p.choices;
      break;
    case operators::ParamType::Text:
      d["type"] = "text";
      d["default"] = p.default_text;
      break;
  }
  // Set when the default is a statistic of the image (the fixed default is then unused).
  d["default_from"] = p.image_default == operators::ImageDefault::None ? py::object(py::none())
                                                                       : py::object(py::str(image_default_name(p.image_default)));
  return d;
}

}  // namespace

py::dict operator_dict(const operators::OperatorDef& op) {
  py::dict d;
  d["name"] = op.name;
  d["summary"] = op.summary;
  d["citation"] = op.citation;
  d["kind"] = operators::kind_name(op.default_kind);
  // Registry operators are global (per pixel): they need the beauty only.
  d["scope"] = "global";
  py::list params;
  for (const auto& p : op.params) params.append(param_dict(p));
  d["params"] = params;
  return d;
}

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
        py::list out;
        for (const auto& op : operators::registry()) out.append(operator_dict(op));
        return out;
      },
      "Every registry operator as a dict: name, summary, citation, kind, scope, params (each a dict: "
      "name, type, default, min/max or choices, default_from, help).");
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
