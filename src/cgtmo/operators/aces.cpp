// Two fits of the ACES RRT+ODT: Stephen Hill's (matrices around a rational curve) and
// Krzysztof Narkowicz's (one rational curve on Rec.709 values).
#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

// Hill's RRT+ODT fit, in the space his input matrix leads to.
struct HillCurve {
  template <class T>
  T operator()(T v) const {
    const T a = v * (v + T(0.0245786)) - T(0.000090537);
    const T b = v * (T(0.983729) * v + T(0.4329510)) + T(0.238081);
    return a / b;
  }
};

color::Mat3 hill_input_matrix() {
  color::Mat3 m;  // sRGB -> (ODT_SAT . RRT_SAT . AP1), rows
  m.m = {{{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}}};
  return m;
}

color::Mat3 hill_output_matrix() {
  color::Mat3 m;  // (ODT_SAT-adjusted AP1) -> sRGB, rows
  m.m = {{{1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}}};
  return m;
}

struct NarkowiczCurve {
  double scale;
  template <class T>
  T operator()(T x) const {
    x *= T(scale);
    const T num = x * (T(2.51) * x + T(0.03));
    const T den = x * (T(2.43) * x + T(0.59)) + T(0.14);
    const T y = num / den;
    return y < T(0) ? T(0) : (y > T(1) ? T(1) : y);
  }
};

}  // namespace

OperatorDef aces_hill_operator() {
  OperatorDef d;
  d.name = "aces-hill";
  d.summary = "ACES RRT+ODT fit: input matrix, rational curve per channel, output matrix";
  d.citation = "Stephen Hill, ACES fitted curve (MJP's BakingLab ACES.hlsl), 2016";
  d.default_kind = Kind::PerChannel;
  d.make = [](const ParamValues&) {
    CurveOptions o;
    o.input_matrix = hill_input_matrix();
    o.output_matrix = hill_output_matrix();
    return make_curve_evaluator(HillCurve{}, o);
  };
  return d;
}

OperatorDef aces_narkowicz_operator() {
  OperatorDef d;
  d.name = "aces-narkowicz";
  d.summary = "Narkowicz's ACES fit x(2.51x+0.03)/(x(2.43x+0.59)+0.14), clamped to [0, 1]";
  d.citation = "Krzysztof Narkowicz, ACES Filmic Tone Mapping Curve, 2016";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("scale", 1.0, 1e-4, 1e4, "input multiplier before the curve (0.6: the guide's aces_approx)"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    return make_curve_evaluator(NarkowiczCurve{v.number("scale")}, curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
