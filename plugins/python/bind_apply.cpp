// Tone mapping of arrays and files through pipeline::Applier, the function `cgtmo apply` runs.
#include "bindings.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/pipeline/apply_file.h"

namespace cgtmo::python {

namespace {

pipeline::ApplyOptions make_options(const std::string& op, const py::object& params, double exposure, bool encode,
                                    const std::string& config, const std::string& display, const std::string& view,
                                    const std::string& layer, const std::string& colorspace,
                                    std::vector<std::string>* warnings) {
  pipeline::ApplyOptions o;
  o.op = op;
  o.params = params_from_dict(params);
  o.exposure_ev = exposure;
  o.encode_display = encode;
  o.colorconfig = config;
  o.display = display;
  o.view = view;
  o.layer = layer;
  o.colorspace = colorspace;
  o.warn = [warnings](const std::string& msg) { warnings->push_back(msg); };
  return o;
}

py::dict report_dict(const pipeline::ApplyReport& r, const std::vector<std::string>& warnings) {
  py::dict d;
  d["width"] = r.width;
  d["height"] = r.height;
  d["channels"] = r.channels;
  d["layer"] = r.layer;
  d["op"] = r.tonemap.op ? r.tonemap.op->name : std::string();
  d["params"] = params_dict(r.tonemap.params);
  d["display"] = r.display;
  d["view"] = r.view;
  d["config"] = r.config_origin;
  d["colorspace"] = r.input_space;
  d["warnings"] = warnings;
  return d;
}

}  // namespace

void bind_apply(py::module_& m) {
  m.def(
      "apply",
      [](const py::object& image, const std::string& op, const py::object& params, double exposure, bool encode,
         const std::string& config, const std::string& display, const std::string& view, bool with_report,
         const std::string& colorspace) -> py::object {
        // Integers are display-referred code values (an 8-bit PNG read as uint8): tone-mapped as
        // light they would be mapped twice, and no colour space of a config takes 0..255.
        if (py::isinstance<py::array>(image)) {
          const char kind = py::reinterpret_borrow<py::array>(image).dtype().kind();
          if (kind == 'u' || kind == 'i' || kind == 'b')
            throw UsageError("image is an integer array (" + std::string(py::str(py::reinterpret_borrow<py::array>(image).dtype())) +
                             "): display-referred code values, not light; convert to float linear light first "
                             "(for sRGB-encoded 8-bit: decode the sRGB curve of values / 255), or use apply_file on the file");
        }
        auto in = as_image(image, "image", 3, 4);
        std::vector<std::string> warnings;
        const pipeline::Applier applier(
            make_options(op, params, exposure, encode, config, display, view, "", colorspace, &warnings));
        // A new array: the caller's is never modified.
        py::array_t<float, py::array::c_style> out({in.shape(0), in.shape(1), in.shape(2)});
        std::copy(in.data(), in.data() + in.size(), out.mutable_data());
        pipeline::ApplyReport rep;
        {
          py::gil_scoped_release nogil;
          rep = applier.apply_pixels(out.mutable_data(), int(out.shape(1)), int(out.shape(0)), int(out.shape(2)));
        }
        if (!with_report) return std::move(out);
        return py::make_tuple(out, report_dict(rep, warnings));
      },
      py::arg("image"), py::arg("op") = "drago", py::arg("params") = py::none(), py::arg("exposure") = 0.0,
      py::arg("encode") = true, py::arg("config") = "", py::arg("display") = "", py::arg("view") = "",
      py::arg("report") = false, py::arg("colorspace") = "",
      "Tone-maps a linear H x W x 3 (or x 4, alpha passes through) array with a registry operator, as "
      "`cgtmo apply` does: conversion from `colorspace` (a colour space of the OCIO config; \"\": the "
      "config's scene_linear role) to linear Rec.709, non-finite policy, exposure (stops), operator, then OpenColorIO display "
      "encoding (encode=False: display-linear output). Returns a new float32 array in [0, 1], or "
      "(array, report dict) with report=True.");

  m.def(
      "apply_file",
      [](const std::string& in, const std::string& out, const std::string& op, const py::object& params,
         double exposure, bool encode, const std::string& config, const std::string& display, const std::string& view,
         const std::string& layer, const std::string& colorspace, const std::string& bit_depth,
         const std::string& compression) {
        std::vector<std::string> warnings;
        pipeline::ApplyOptions options =
            make_options(op, params, exposure, encode, config, display, view, layer, colorspace, &warnings);
        options.output.bit_depth = bit_depth;
        options.output.compression = compression;
        io::check_output_format(out, options.output, encode);
        const pipeline::Applier applier(options);
        pipeline::ApplyReport rep;
        {
          py::gil_scoped_release nogil;
          rep = applier.apply_file(in, out);
        }
        return report_dict(rep, warnings);
      },
      py::arg("input"), py::arg("output"), py::arg("op") = "drago", py::arg("params") = py::none(),
      py::arg("exposure") = 0.0, py::arg("encode") = true, py::arg("config") = "", py::arg("display") = "",
      py::arg("view") = "", py::arg("layer") = "", py::arg("colorspace") = "", py::arg("bit_depth") = "",
      py::arg("compression") = "",
      "Exactly `cgtmo apply INPUT -o OUTPUT [--colorspace NAME] [--bit-depth D] [--compression C]`: reads the "
      "beauty of an EXR (or the layer given), converts it to linear Rec.709 (from `colorspace`, else the "
      "file's chromaticities attribute, else the config's scene_linear role), tone-maps, encodes and writes "
      "OUTPUT atomically (default .png/.jpg 8 bit, .tif 16 bit, .exr float; bit_depth \"8\", \"16\" (PNG, "
      "TIFF), \"half\" (EXR), \"float\" (TIFF, EXR); compression: EXR's, default zip). Returns a report dict (size, layer, resolved params, display/view, "
      "the input colour space as resolved, warnings).");
}

}  // namespace cgtmo::python
