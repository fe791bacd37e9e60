// Drago, Myszkowski, Annen, Chiba 2003, adaptive logarithmic mapping, on luminance by default.
// Conventions (docs/operators.md): luminances are divided by lw_a first (lw_max too); lw_a defaults
// to the log-average with epsilon 1e-4 and lw_max to the image maximum, as pfstmo_drago03; unlike
// pfstmo the ld_max/100 factor is kept (1 at the default) and the result is clamped to [0, 1];
// no exposure correction of lw_a for b != 0.85.
#include <cmath>

#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/operators/drago_curve.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {

DragoCurve make_drago(double b, double ld_max, double lw_max, double lw_a) {
  DragoCurve c;
  c.inv_lw_a = 1.0 / lw_a;
  const double max_scaled = lw_max / lw_a;
  c.inv_max_scaled = 1.0 / max_scaled;
  // 1 / log10(1 + M') as ln 10 / log1p(M'): stays finite when lw_max / lw_a is below 1e-16.
  c.scale = (ld_max / 100.0) * repro::log(10.0) / repro::log1p(max_scaled);
  c.bias_exponent = repro::log(b) / repro::log(0.5);
  return c;
}

OperatorDef drago_operator() {
  OperatorDef d;
  d.name = "drago";
  d.summary = "adaptive logarithmic mapping: log base from 2 to 10 with the pixel's share of lw_max";
  d.citation = "Drago, Myszkowski, Annen, Chiba, Adaptive Logarithmic Mapping for Displaying High Contrast Scenes, Eurographics 2003";
  d.default_kind = Kind::Mixing;
  d.params = {number_param("b", 0.85, 0.5, 1.0, "bias: contrast in the darks (0.7..0.9 usual)"),
              number_param("ld_max", 100, 1, 10000, "display maximum in cd/m^2 (100: output 1 at lw_max)"),
              number_param("lw_max", 1, 1e-6, 1e30, "scene maximum luminance (default: the image's)", ImageDefault::MaxLuminance),
              number_param("lw_a", 1, 1e-6, 1e30, "world adaptation luminance (default: the image's log-average)",
                           ImageDefault::LogAverageLuminance),
              mode_param(Mode::Luminance), saturation_param()};
  d.make = [](const ParamValues& v) {
    return make_curve_evaluator(make_drago(v.number("b"), v.number("ld_max"), v.number("lw_max"), v.number("lw_a")),
                                curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
