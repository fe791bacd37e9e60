// AgX base (no look): inset matrix, log2 encoding over [-12.47393, +4.026069] EV around 0.18,
// the 6th-order polynomial fit of the AgX sigmoid, decoded to display-linear with a 2.2 power, outset
// matrix. Variant: Benjamin Wrensch's "Minimal AgX implementation" (2023) of Troy Sobotka's AgX.
#include <cmath>

#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {
namespace {

constexpr double kMinEv = -12.47393;
constexpr double kMaxEv = 4.026069;

struct AgxCurve {
  template <class T>
  T operator()(T x) const {
    T e = T(repro::log2(x));  // -inf at 0, clamped below
    e = e > T(kMinEv) ? (e < T(kMaxEv) ? e : T(kMaxEv)) : T(kMinEv);
    const T n = (e - T(kMinEv)) / T(kMaxEv - kMinEv);
    const T n2 = n * n, n4 = n2 * n2;
    T s = T(15.5) * n4 * n2 - T(40.14) * n4 * n + T(31.96) * n4 - T(6.868) * n2 * n + T(0.4298) * n2 +
          T(0.1191) * n - T(0.00232);
    s = s > T(0) ? s : T(0);
    return T(repro::pow(s, T(2.2)));
  }
};

color::Mat3 agx_inset() {
  color::Mat3 m;  // rows (the published GLSL lists these column by column)
  m.m = {{{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
          {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
          {0.0423756549057051, 0.0784336, 0.879142973793104}}};
  return m;
}

}  // namespace

OperatorDef agx_operator() {
  OperatorDef d;
  d.name = "agx";
  d.summary = "AgX base: inset matrix, log2 encoding, sigmoid per channel, outset matrix";
  d.citation = "Troy Sobotka, AgX (2022); polynomial fit: Benjamin Wrensch, Minimal AgX Implementation, 2023";
  d.default_kind = Kind::PerChannel;
  d.make = [](const ParamValues&) {
    CurveOptions o;
    o.input_matrix = agx_inset();
    o.output_matrix = agx_inset().inverse();
    return make_curve_evaluator(AgxCurve{}, o);
  };
  return d;
}

}  // namespace cgtmo::operators
