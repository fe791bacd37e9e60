// LUT baking (src/cgtmo/bake): every registry operator into LUTs + the OCIO config, or Drago with
// one render's statistics as a look, exactly as `cgtmo bake` (and `cgtmo bake --scene`).
#include <memory>
#include <optional>

#include "bindings.h"
#include "cgtmo/bake/bake.h"

namespace cgtmo::python {

namespace {

// A Python callable called with each progress line. Baking may call it from worker threads, with
// the GIL released around the bake: take the GIL for the call; an exception in the callback is
// reported as unraisable instead of unwinding through the library.
bake::Progress progress_from(const py::object& callback) {
  if (callback.is_none()) return {};
  auto cb = std::make_shared<py::object>(callback);
  return [cb](const std::string& line) {
    py::gil_scoped_acquire gil;
    try {
      (*cb)(line);
    } catch (py::error_already_set& e) {
      e.discard_as_unraisable("cgtmo.bake progress callback");
    }
  };
}

bake::BakeOptions bake_options(const std::string& luts_dir, const std::string& config_dir,
                               const std::optional<double>& max_error, const py::object& progress,
                               const std::string& command_line) {
  bake::BakeOptions o;
  o.luts_dir = luts_dir;
  o.config_dir = config_dir;
  o.max_error_cv = max_error;
  o.progress = progress_from(progress);
  o.command_line = command_line.empty() ? "cgtmo.bake() (Python)" : command_line;
  return o;
}

py::dict audit_dict(const bake::AuditResult& a) {
  py::dict d;
  d["max_cv"] = a.max_cv;
  d["p999_cv"] = a.p999_cv;
  return d;
}

}  // namespace

void bind_bake(py::module_& m) {
  m.def(
      "bake",
      [](const std::string& luts_dir, const std::string& config_dir, const std::string& report,
         std::optional<double> max_error, const py::object& progress, const std::string& command_line) {
        auto o = bake_options(luts_dir, config_dir, max_error, progress, command_line);
        o.report_path = report;
        bake::BakeResult r;
        {
          py::gil_scoped_release nogil;
          r = bake::bake_all(o);
        }
        o.progress = {};  // drop the callback's reference while the GIL is held
        py::list ops;
        for (const auto& ob : r.ops) {
          py::dict d;
          d["name"] = ob.subject.def->name;
          d["params"] = ob.subject.params_text();
          d["representation"] = ob.choice.lut.rep.describe();
          d["met"] = ob.choice.met;
          d["budget_cv"] = ob.budget_cv;
          d["shipped"] = audit_dict(ob.shipped);
          d["cube"] = audit_dict(ob.cube);
          d["clf"] = audit_dict(ob.clf);
          d["lut_file"] = ob.lut_file;
          d["cube_file"] = ob.cube_file;
          d["clf_file"] = ob.clf_file;
          d["lut_bytes"] = ob.lut_bytes;
          d["ocio_mpix"] = ob.ocio_mpix;
          ops.append(d);
        }
        py::dict out;
        out["ops"] = ops;
        out["missed"] = r.missed;
        return out;
      },
      py::arg("luts_dir") = "", py::arg("config_dir") = "", py::arg("report") = "",
      py::arg("max_error") = py::none(), py::arg("progress") = py::none(), py::arg("command_line") = "",
      "`cgtmo bake`: every registry operator into LUT files and exports in luts_dir and config.ocio in "
      "config_dir (both must exist), the accuracy report if given; max_error (10-bit code values) makes the "
      "budget strict. progress: a callable taking each progress line. Returns {'ops': [...], 'missed': [...]}, "
      "one dict per operator (representation, errors of the shipped view and exports, files).");

  m.def(
      "bake_scene",
      [](const std::string& render, const std::string& name, const std::string& luts_dir,
         const std::string& config_dir, std::optional<double> max_error, const py::object& progress) {
        auto o = bake_options(luts_dir, config_dir, max_error, progress, "");
        bake::SceneBakeResult r;
        {
          py::gil_scoped_release nogil;
          r = bake::bake_scene(render, name, o);
        }
        o.progress = {};
        py::dict d;
        d["lut"] = r.lut_path;
        d["config"] = r.config_path;
        d["look"] = r.look_name;
        d["params"] = r.subject.params_text();
        d["audit"] = audit_dict(r.audit);
        py::dict stats;
        stats["max_channel"] = r.stats.max_channel;
        stats["max_luminance"] = r.stats.max_luminance;
        stats["log_average_luminance"] = r.stats.log_average_luminance;
        d["stats"] = stats;
        return d;
      },
      py::arg("render"), py::arg("name") = "", py::arg("luts_dir") = "", py::arg("config_dir") = "",
      py::arg("max_error") = py::none(), py::arg("progress") = py::none(),
      "`cgtmo bake --scene`: Drago with this render's statistics as a LUT in luts_dir, and a look and view "
      "'drago-NAME' added to a copy of config_dir/config.ocio (without one, of the built-in displays) named "
      "config_dir/NAME.ocio.");
}

}  // namespace cgtmo::python
