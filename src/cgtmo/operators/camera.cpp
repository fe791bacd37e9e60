// A camera response curve (DoRF layout) per channel; `iso` is the input value that reaches the
// curve's top irradiance, so raising it stretches the irradiance axis.
#include <fstream>
#include <memory>
#include <sstream>

#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/operators/camera_table.h"
#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

struct CameraCurve {
  std::shared_ptr<const CameraResponse> response;
  double inv_iso;
  template <class T>
  T operator()(T x) const {
    return T(sample_response(*response, double(x) * inv_iso));
  }
};

std::vector<CameraResponse> load_table(const std::string& path) {
  if (path == "builtin") return builtin_camera_responses();
  // A FIFO or device would block or never end.
  if (const std::string why = io::input_file_problem(path); !why.empty())
    throw DataError("cannot read camera table '" + path + "': " + why);
  std::ifstream f(path, std::ios::binary);
  if (!f) throw DataError("cannot read camera table '" + path + "'");
  std::ostringstream s;
  s << f.rdbuf();
  return parse_dorf(s.str(), path);
}

}  // namespace

OperatorDef camera_operator() {
  OperatorDef d;
  d.name = "camera";
  d.summary = "a measured-style camera response curve (DoRF table) per channel";
  d.citation = "Grossberg and Nayar, Database of Response Functions (DoRF), Columbia University, 2003";
  d.default_kind = Kind::PerChannel;
  ParamSpec table;
  table.name = "table";
  table.type = ParamType::Text;
  table.default_text = "builtin";
  table.help = "a DoRF-format text file, or 'builtin' (cgtmo's synthetic film curves)";
  ParamSpec curve;
  curve.name = "curve";
  curve.type = ParamType::Text;
  curve.default_text = "";
  curve.help = "name of the curve in the table (default: the first)";
  d.params = {table, curve, number_param("iso", 1.0, 1e-4, 65504, "input value mapped to the top of the curve"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    const auto table = load_table(v.text("table"));
    const std::string& want = v.text("curve");
    const CameraResponse* chosen = want.empty() ? &table.front() : nullptr;
    for (const auto& c : table)
      if (!chosen && c.name == want) chosen = &c;
    if (!chosen) throw UsageError("camera: no curve named '" + want + "' in " + v.text("table"));
    CameraCurve c{std::make_shared<const CameraResponse>(*chosen), 1.0 / v.number("iso")};
    return make_curve_evaluator(c, curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
