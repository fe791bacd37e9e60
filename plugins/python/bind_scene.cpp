// The scene operators (CG-TMO, WLS-TMO; the registry's entries of scope 'scene'): what they read
// and the file pipeline that reads a render with its passes, probe and sidecar (cgtmo/local/apply_scene.h, as `cgtmo apply --op cgtmo`).
#include "bindings.h"
#include "cgtmo/local/apply_scene.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/errors.h"

namespace cgtmo::python {

void bind_scene(py::module_& m) {
  m.def(
      "scene_needs",
      [](const std::string& name, const py::object& params) {
        const auto& op = local::find_scene_operator(name);  // UsageError for a pixel operator
        const auto v = operators::resolve_params(op, params_from_dict(params), nullptr);
        py::dict d;
        // Depth marks the background; light groups, probe and sidecar give Lw_max and Lw_a.
        d["gbuffer"] = local::needs_gbuffer(local::options_from(op, v));
        d["depth"] = true;
        d["light_groups"] = true;
        d["probe"] = true;
        d["sidecar"] = true;
        return d;
      },
      py::arg("op"), py::arg("params") = py::none(),
      "What a scene operator with these parameters reads besides the beauty: gbuffer (Position, "
      "Normal, DiffCol), depth, light_groups, probe, sidecar.");

  m.def(
      "apply_scene",
      [](const std::string& in, const std::string& out, const std::string& op, const py::object& params,
         double exposure, bool encode, const std::string& config, const std::string& display, const std::string& view,
         const std::string& layer, const std::string& probe, const std::string& sidecar, const std::string& colorspace) {
        std::vector<std::string> warnings;
        local::SceneApplyOptions o;
        o.op = op;
        o.params = params_from_dict(params);
        o.exposure_ev = exposure;
        o.layer = layer;
        o.encode_display = encode;
        o.colorconfig = config;
        o.display = display;
        o.view = view;
        o.probe_path = probe;
        o.sidecar_path = sidecar;
        o.colorspace = colorspace;
        o.warn = [&warnings](const std::string& msg) { warnings.push_back(msg); };
        local::SceneApplyReport r;
        {
          py::gil_scoped_release nogil;
          r = local::apply_scene_file(o, in, out);
        }
        py::dict d;
        d["width"] = r.width;
        d["height"] = r.height;
        d["channels"] = r.channels;
        d["layer"] = layer;
        d["op"] = op;
        d["params"] = params_dict(r.params);
        d["display"] = r.display;
        d["view"] = r.view;
        d["config"] = r.config_origin;
        d["colorspace"] = r.input_space;
        d["explain"] = local::describe(r.explain);
        d["notes"] = r.notes;
        d["warnings"] = warnings;
        return d;
      },
      py::arg("input"), py::arg("output"), py::arg("op") = "cgtmo", py::arg("params") = py::none(),
      py::arg("exposure") = 0.0, py::arg("encode") = true, py::arg("config") = "", py::arg("display") = "",
      py::arg("view") = "", py::arg("layer") = "", py::arg("probe") = "", py::arg("sidecar") = "",
      py::arg("colorspace") = "",
      "Exactly `cgtmo apply INPUT -o OUTPUT --op cgtmo|wls [--colorspace NAME]`: reads the render with the "
      "passes the operator needs, converts its colour passes (and the probe) to linear Rec.709 as apply_file "
      "does, NAME.probe.exr and NAME.json beside it (or probe/sidecar given), tone-maps, encodes and writes "
      "OUTPUT atomically. Returns a report dict with the resolved params, explain lines (statistics, guide "
      "decisions) and notes on what was missing.");
}

}  // namespace cgtmo::python
