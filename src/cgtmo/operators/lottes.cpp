// Timothy Lottes' curve x^a / (x^(a d) b + c), with b and c solved so that mid_in maps to mid_out
// and hdr_max to 1.
#include <cmath>

#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {
namespace {

struct LottesCurve {
  double a, ad, b, c;
  template <class T>
  T operator()(T x) const {
    // x^a / (x^(ad) b + c); above 1 divided through by x^a, so that no power overflows for
    // large x and contrast (inf / inf would be NaN).
    if (x <= T(1)) return T(repro::pow(x, T(a))) / (T(repro::pow(x, T(ad))) * T(b) + T(c));
    return T(1) / (T(b) * T(repro::pow(x, T(ad - a))) + T(c) * T(repro::pow(x, T(-a))));
  }
};

LottesCurve make_lottes(double a, double d, double hdr_max, double mid_in, double mid_out) {
  const double ad = a * d;
  const double mi_a = repro::pow(mid_in, a), mi_ad = repro::pow(mid_in, ad);
  const double hm_a = repro::pow(hdr_max, a), hm_ad = repro::pow(hdr_max, ad);
  const double den = (hm_ad - mi_ad) * mid_out;
  const double b = (-mi_a + hm_a * mid_out) / den;
  const double c = (hm_ad * mi_a - hm_a * mi_ad * mid_out) / den;
  return {a, ad, b, c};
}

}  // namespace

OperatorDef lottes_operator() {
  OperatorDef d;
  d.name = "lottes";
  d.summary = "x^a / (x^(a d) b + c) through (mid_in, mid_out) and (hdr_max, 1)";
  d.citation = "Timothy Lottes, Advanced Techniques and Optimization of HDR Color Pipelines, GDC 2016";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("contrast", 1.6, 0.1, 10, "a"),
              number_param("shoulder", 0.977, 0.01, 1.5, "d"),
              number_param("hdr_max", 8.0, 1.0, 65504, "input mapped to 1"),
              number_param("mid_in", 0.18, 1e-4, 1.0, "mid-grey input"),
              number_param("mid_out", 0.267, 1e-4, 1.0, "mid-grey output"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    return make_curve_evaluator(make_lottes(v.number("contrast"), v.number("shoulder"), v.number("hdr_max"),
                                            v.number("mid_in"), v.number("mid_out")),
                                curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
