// Hajime Uchimura's Gran Turismo curve: power toe, linear middle, exponential shoulder, blended.
#include <algorithm>
#include <cmath>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {
namespace {

struct UchimuraCurve {
  double P, a, m, l, c, b;  // max brightness, contrast, linear start, linear length, black tightness, pedestal
  template <class T>
  T operator()(T x) const {
    const double l0 = ((P - m) * l) / a;
    const double S0 = m + l0;
    const double S1 = m + a * l0;
    const double C2 = (a * P) / (P - S1);
    const double CP = -C2 / P;
    T t = x / T(m);  // smoothstep(0, m, x)
    t = t < T(0) ? T(0) : (t > T(1) ? T(1) : t);
    const T w0 = T(1) - t * t * (T(3) - T(2) * t);
    const T w2 = x < T(S0) ? T(0) : T(1);
    const T w1 = T(1) - w0 - w2;
    // The toe only where its weight w0 is non-zero: (x / m)^c overflows for large x and black
    // tightness, and inf * 0 would be NaN.
    const T toe = x < T(m) ? T(m) * T(repro::pow(x / T(m), T(c))) + T(b) : T(0);
    const T lin = T(m) + T(a) * (x - T(m));
    const T shoulder = T(P) - T(P - S1) * T(repro::exp(T(CP) * (x - T(S0))));
    return toe * w0 + lin * w1 + shoulder * w2;
  }
};

}  // namespace

OperatorDef uchimura_operator() {
  OperatorDef d;
  d.name = "uchimura";
  d.summary = "Gran Turismo curve: toe, linear section and shoulder with smooth weights";
  d.citation = "Hajime Uchimura, HDR Theory and Practice, CEDEC 2017 (Gran Turismo Sport)";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("max_brightness", 1.0, 0.1, 10, "P: the shoulder's asymptote"),
              number_param("contrast", 1.0, 0.01, 10, "a: slope of the linear section"),
              number_param("linear_start", 0.22, 0.01, 0.99,
                           "m: where the linear section starts (unless given: 0.22, or 0.22 x max_brightness below 1)"),
              number_param("linear_length", 0.4, 0.0, 0.99, "l: length of the linear section"),
              number_param("black", 1.33, 0.1, 10, "c: black tightness (toe power)"),
              number_param("pedestal", 0.0, 0.0, 0.5, "b: output added in the toe"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    const double P = v.number("max_brightness");
    // The default linear start keeps its share of the range when the asymptote is lowered, so
    // every max_brightness the range allows works with the other defaults.
    const double m = v.given("linear_start") ? v.number("linear_start") : std::min(v.number("linear_start"), 0.22 * P);
    // The shoulder P - (P - S1) e^(-C2 (x - S0) / P) only rises toward P when P > S1, i.e. P > m.
    if (!(P > m))
      throw UsageError("uchimura: max_brightness (" + std::to_string(P) + ") must be above linear_start (" +
                       std::to_string(m) + ")");
    UchimuraCurve c{P, v.number("contrast"), m, v.number("linear_length"), v.number("black"), v.number("pedestal")};
    return make_curve_evaluator(c, curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
