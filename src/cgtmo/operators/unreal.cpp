// Unreal Engine 4's filmic tone curve (FilmToneMap, UE 4.15+): a logistic toe and shoulder joined
// by a straight line in log10 space, applied per channel in ACES AP1.
#include <cmath>
#include <limits>

#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {
namespace {

struct UnrealCurve {
  double slope, toe, shoulder, black_clip, white_clip;
  double toe_match, shoulder_match, straight_match, toe_scale, shoulder_scale;

  template <class T>
  T operator()(T x) const {
    // x = 0 would give log10 = -inf and then -inf * 0 = NaN in the blend below: floor at the
    // smallest positive value, where the toe is already at -black_clip.
    const T log_x = T(repro::log10(x > T(0) ? x : std::numeric_limits<T>::denorm_min()));
    const T straight = T(slope) * (log_x + T(straight_match));
    T toe_part = T(-black_clip) + T(2 * toe_scale) / (T(1) + T(repro::exp(T(-2 * slope / toe_scale) * (log_x - T(toe_match)))));
    T shoulder_part =
        T(1 + white_clip) - T(2 * shoulder_scale) / (T(1) + T(repro::exp(T(2 * slope / shoulder_scale) * (log_x - T(shoulder_match)))));
    toe_part = log_x < T(toe_match) ? toe_part : straight;
    shoulder_part = log_x > T(shoulder_match) ? shoulder_part : straight;
    T t = (log_x - T(toe_match)) / T(shoulder_match - toe_match);
    t = t > T(0) ? (t < T(1) ? t : T(1)) : T(0);
    if (shoulder_match < toe_match) t = T(1) - t;
    t = (T(3) - T(2) * t) * t * t;
    return toe_part + (shoulder_part - toe_part) * t;
  }
};

UnrealCurve make_unreal(double slope, double toe, double shoulder, double black_clip, double white_clip) {
  UnrealCurve c{slope, toe, shoulder, black_clip, white_clip, 0, 0, 0, 0, 0};
  c.toe_scale = 1.0 + black_clip - toe;
  c.shoulder_scale = 1.0 + white_clip - shoulder;
  const double in_match = 0.18, out_match = 0.18;
  if (toe > 0.8) {  // 0.18 lies on the straight section
    c.toe_match = (1.0 - toe - out_match) / slope + repro::log10(in_match);
  } else {  // 0.18 lies on the toe's curve: solve the logistic for the match point
    const double bt = (out_match + black_clip) / c.toe_scale - 1.0;
    c.toe_match = repro::log10(in_match) - 0.5 * repro::log((1.0 + bt) / (1.0 - bt)) * (c.toe_scale / slope);
  }
  c.straight_match = (1.0 - toe) / slope - c.toe_match;
  c.shoulder_match = shoulder / slope - c.straight_match;
  return c;
}

}  // namespace

OperatorDef unreal_operator() {
  OperatorDef d;
  d.name = "unreal";
  d.summary = "UE4 filmic: log-space toe/straight/shoulder per channel in ACES AP1";
  d.citation = "Epic Games, Unreal Engine 4.15 filmic tonemapper (FilmToneMap), ACES-based, 2017";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("slope", 0.88, 0.1, 3, "steepness of the straight section"),
              number_param("toe", 0.55, 0.0, 0.99, "toe size"),
              number_param("shoulder", 0.26, 0.0, 0.99, "shoulder size"),
              number_param("black_clip", 0.0, 0.0, 0.5, "output below 0 reached by the toe"),
              number_param("white_clip", 0.04, 0.0, 0.5, "output above 1 reached by the shoulder")};
  d.make = [](const ParamValues& v) {
    CurveOptions o;
    o.input_matrix = color::rec709_to_ap1();
    o.output_matrix = color::ap1_to_rec709();
    return make_curve_evaluator(make_unreal(v.number("slope"), v.number("toe"), v.number("shoulder"),
                                            v.number("black_clip"), v.number("white_clip")),
                                o);
  };
  return d;
}

}  // namespace cgtmo::operators
