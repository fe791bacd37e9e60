// Image quality metrics (src/cgtmo/metrics).
#include "bindings.h"
#include "cgtmo/errors.h"
#include "cgtmo/local/evaluate.h"
#include "cgtmo/metrics/tmqi.h"

namespace cgtmo::python {

namespace {

py::dict tmqi_dict(const metrics::TmqiResult& r) {
  py::dict d;
  d["Q"] = r.q;
  d["S"] = r.s;
  d["N"] = r.n;
  d["S_local"] = std::vector<double>(r.s_local.begin(), r.s_local.end());
  return d;
}

}  // namespace

void bind_metrics(py::module_& m) {
  m.def(
      "tmqi",
      [](const py::object& hdr, const py::object& ldr) {
        const auto h = as_image(hdr, "hdr", 3, 4);
        const auto l = as_image(ldr, "ldr", 3, 4);
        if (h.shape(0) != l.shape(0) || h.shape(1) != l.shape(1))
          throw UsageError("hdr and ldr differ in size: " + std::to_string(h.shape(1)) + "x" + std::to_string(h.shape(0)) +
                           " vs " + std::to_string(l.shape(1)) + "x" + std::to_string(l.shape(0)));
        metrics::TmqiResult r;
        {
          py::gil_scoped_release nogil;
          r = metrics::tmqi_rgb(h.data(), int(h.shape(2)), l.data(), int(l.shape(2)), int(h.shape(1)), int(h.shape(0)));
        }
        return tmqi_dict(r);
      },
      py::arg("hdr"), py::arg("ldr"),
      "TMQI (Yeganeh and Wang 2013) of a tone-mapped image: hdr linear RGB(A), ldr display-encoded RGB(A) on "
      "a 0-255 scale (e.g. a uint8 PNG as read). Returns Q, S, N and S_local (per scale, finest first). "
      "Images must be at least 161x161.");

  m.def(
      "evaluate_scene",
      [](const std::string& path) {
        local::SceneScores r;
        {
          py::gil_scoped_release nogil;
          r = local::evaluate_scene(path);
        }
        py::dict scores;
        for (const auto& s : r.scores) {
          py::dict d = tmqi_dict(s.tmqi);
          d["ms"] = s.ms;
          scores[py::str(s.method)] = d;
        }
        py::dict d;
        d["name"] = r.name;
        d["width"] = r.width;
        d["height"] = r.height;
        d["scores"] = scores;
        d["notes"] = r.notes;
        return d;
      },
      py::arg("exr"),
      "What `cgtmo eval --scenes` computes for one render: TMQI of each method (global drago, bilateral, "
      "cgtmo with each filter, wls, and the adaptation study), each output sRGB-encoded and quantised to "
      "8 bits. Returns name, width, height, scores {method: {Q, S, N, S_local, ms}} and the reader's notes.");
}

}  // namespace cgtmo::python
