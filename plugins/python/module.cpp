// The `cgtmo` Python module. Library errors become Python exceptions carrying the library's
// one-line message: UsageError -> ValueError, DataError -> cgtmo.DataError (an OSError).
#include "bindings.h"
#include "cgtmo/errors.h"
#include "cgtmo/pipeline/request.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/version.h"

namespace cgtmo::python {

py::array_t<float, py::array::c_style> as_image(const py::handle& obj, const char* what, int min_channels, int max_channels) {
  auto arr = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!arr) throw UsageError(std::string(what) + " must be a numeric array (H x W x C)");
  const auto shape_text = [&] {
    std::string s;
    for (py::ssize_t i = 0; i < arr.ndim(); ++i) s += (i ? "x" : "") + std::to_string(arr.shape(i));
    return s.empty() ? std::string("a scalar") : s;
  };
  if (arr.ndim() != 3 || arr.shape(2) < min_channels || arr.shape(2) > max_channels)
    throw UsageError(std::string(what) + " must be H x W x C with C in [" + std::to_string(min_channels) + ", " +
                     std::to_string(max_channels) + "], got " + shape_text());
  if (arr.shape(0) < 1 || arr.shape(1) < 1) throw UsageError(std::string(what) + " is empty (" + shape_text() + ")");
  return arr;
}

std::map<std::string, std::string> params_from_dict(const py::object& params) {
  std::map<std::string, std::string> out;
  if (params.is_none()) return out;
  if (!py::isinstance<py::dict>(params)) throw UsageError("params must be a dict of name -> value");
  for (const auto& [k, v] : params.cast<py::dict>()) {
    const std::string key = py::str(k);
    if (py::isinstance<py::bool_>(v)) throw UsageError("parameter '" + key + "' must be a number or text, not a bool");
    out[key] = py::isinstance<py::float_>(v) ? std::string(py::repr(v)) : std::string(py::str(v));
  }
  return out;
}

}  // namespace cgtmo::python

PYBIND11_MODULE(cgtmo, m) {
  namespace py = pybind11;
  using namespace cgtmo::python;
  m.doc() = "cgtmo: tone mapping for CG renders (bindings over the C++ library; see docs/plugins.md)";
  m.attr("__version__") = cgtmo::version();  // the CMake project version, as `cgtmo --version` prints it
  // The exposure range apply(), apply_file() and apply_scene() accept, in stops either way (the
  // Blender add-on bounds its Exposure property with it).
  m.attr("max_exposure_stops") = cgtmo::pipeline::kMaxExposureStops;

  static py::exception<cgtmo::DataError> data_error(m, "DataError", PyExc_OSError);
  data_error.doc() = "The data is wrong: unreadable, truncated or corrupt file, missing channels.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const cgtmo::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const cgtmo::DataError& e) {
      data_error(e.what());
    }
  });

  m.def("set_threads", &cgtmo::set_threads, py::arg("n"),
        ("The library's worker threads for every later call, 0 to " + std::to_string(cgtmo::kMaxThreads) +
         " (0: the CPUs this process is allotted; outside the range: ValueError). OpenImageIO's process-wide "
         "\"threads\" attribute, the host's, is not changed.")
            .c_str());
  m.attr("max_threads") = cgtmo::kMaxThreads;  // the range's top, as the CLI's --threads takes it

  bind_operators(m);
  bind_apply(m);
  bind_display(m);
  bind_metrics(m);
  bind_scene(m);
  bind_bake(m);
}
