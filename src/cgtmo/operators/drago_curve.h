#pragma once
// Drago's curve as a functor: shared by the global `drago` operator and the local CG-TMO pipeline.
#include <cmath>
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {

// Ld = scale * ln(1 + Lw') / ln(2 + 8 (Lw' / Lmax')^(ln b / ln 0.5)),  Lw' = Lw / lw_a.
struct DragoCurve {
  double inv_lw_a = 1, inv_max_scaled = 1, scale = 1, bias_exponent = 1;
  template <class T>
  T operator()(T x) const {
    const T xs = x * T(inv_lw_a);
    const T denom = T(repro::log(T(2) + T(8) * T(repro::pow(xs * T(inv_max_scaled), T(bias_exponent)))));
    return T(scale) * T(repro::log1p(xs)) / denom;
  }
};

DragoCurve make_drago(double b, double ld_max, double lw_max, double lw_a);

}  // namespace cgtmo::operators
