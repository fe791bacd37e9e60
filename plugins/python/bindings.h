#pragma once
// Shared helpers of the binding files. Each concern has one bind_<concern>() in its own file;
// binding a new library function is one m.def line there (or one new file and one call in
// module.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <string>

#include "cgtmo/operators/operator.h"

namespace cgtmo::python {

namespace py = pybind11;

// An image as the library wants it: C-contiguous float32, H x W x C. Converts (copies) other
// dtypes and layouts; throws UsageError (-> ValueError) naming the shape it got.
py::array_t<float, py::array::c_style> as_image(const py::handle& obj, const char* what, int min_channels, int max_channels);

// Operator parameters from a Python dict: values may be str, int or float (floats are passed as
// their shortest round-trip repr, so the library parses back the same double).
std::map<std::string, std::string> params_from_dict(const py::object& params);

// An operator's data as a dict: operators::describe() (the JSON `cgtmo list --json` prints) as
// Python data, so both faces show the same fields and spellings. Resolved parameter values as a dict.
py::object operator_dict(const operators::OperatorDef& op);
py::dict params_dict(const operators::ParamValues& v);

void bind_operators(py::module_& m);
void bind_apply(py::module_& m);
void bind_display(py::module_& m);
void bind_metrics(py::module_& m);
void bind_scene(py::module_& m);
void bind_bake(py::module_& m);

}  // namespace cgtmo::python
