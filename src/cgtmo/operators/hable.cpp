// John Hable's filmic curves: the Uncharted 2 rational curve (GDC 2010) and his later piecewise
// power curve ("Filmic Tonemapping with Piecewise Power Curves", 2017).
#include <cmath>

#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {
namespace {

struct Uncharted2Coefficients {
  double a, b, c, d, e, f;
  template <class T>
  T partial(T x) const {
    return ((x * (T(a) * x + T(c * b)) + T(d * e)) / (x * (T(a) * x + T(b)) + T(d * f))) - T(e / f);
  }
};

struct Uncharted2Curve {
  Uncharted2Coefficients k;
  double exposure_bias;
  double white_scale;  // 1 / partial(white)
  template <class T>
  T operator()(T x) const {
    return k.partial(x * T(exposure_bias)) * T(white_scale);
  }
};

// One power segment: y = scale_y * A * ((x - offset_x) * scale_x)^B + offset_y, 0 where the base <= 0.
struct PowerSegment {
  double offset_x = 0, offset_y = 0, scale_x = 1, scale_y = 1, ln_a = 0, b = 1;
  template <class T>
  T eval(T x) const {
    const T base = (x - T(offset_x)) * T(scale_x);
    const T y = base > T(0) ? T(repro::exp(T(ln_a) + T(b) * repro::log(base))) : T(0);
    return y * T(scale_y) + T(offset_y);
  }
};

// Toe (power), linear part (a power of a line, for gamma), shoulder (a mirrored power), in x / W.
struct PiecewiseCurve {
  double inv_w = 1, x0 = 0, x1 = 0;
  PowerSegment toe, middle, shoulder;
  template <class T>
  T operator()(T x) const {
    const T nx = x * T(inv_w);
    return nx < T(x0) ? toe.eval(nx) : nx < T(x1) ? middle.eval(nx) : shoulder.eval(nx);
  }
};

// Power y = A x^B through (x, y) with slope m: B = m x / y, ln A = ln y - B ln x.
void solve_power(double x, double y, double m, double& ln_a, double& b) {
  b = m * x / y;
  ln_a = repro::log(y) - b * repro::log(x);
}

// Builds the curve from the artist-facing parameters, following the construction of Hable's post:
// toe and shoulder lengths place the linear section's ends in a perceptual (2.2) space, shoulder
// strength adds stops of range above the linear section, the angle adds overshoot.
PiecewiseCurve make_piecewise(double toe_strength, double toe_length, double shoulder_strength,
                              double shoulder_length, double shoulder_angle, double gamma) {
  const double perceptual_gamma = 2.2;
  double x0 = toe_length * 0.5;
  double y0 = (1.0 - toe_strength) * x0;
  const double remaining_y = 1.0 - y0;
  const double initial_w = x0 + remaining_y;
  const double y1_offset = (1.0 - shoulder_length) * remaining_y;
  double x1 = x0 + y1_offset;
  double y1 = y0 + y1_offset;
  const double w = initial_w + (repro::exp2(shoulder_strength) - 1.0);
  x0 = repro::pow(x0, perceptual_gamma);
  y0 = repro::pow(y0, perceptual_gamma);
  x1 = repro::pow(x1, perceptual_gamma);
  y1 = repro::pow(y1, perceptual_gamma);
  double overshoot_x = (w * 2.0) * shoulder_angle * shoulder_strength;
  double overshoot_y = 0.5 * shoulder_angle * shoulder_strength;

  // Normalise x to [0, 1] over [0, W].
  PiecewiseCurve c;
  c.inv_w = 1.0 / w;
  x0 /= w;
  x1 /= w;
  overshoot_x /= w;

  // Linear section y = (m x + b)^gamma.
  const double m = (y1 - y0) / (x1 - x0);
  const double b = y0 - x0 * m;
  c.middle.offset_x = -b / m;
  c.middle.ln_a = gamma * repro::log(m);
  c.middle.b = gamma;
  const double toe_slope = gamma * m * repro::pow(m * x0 + b, gamma - 1.0);
  const double shoulder_slope = gamma * m * repro::pow(m * x1 + b, gamma - 1.0);
  y0 = std::max(1e-5, repro::pow(y0, gamma));
  y1 = std::max(1e-5, repro::pow(y1, gamma));
  overshoot_y = repro::pow(1.0 + overshoot_y, gamma) - 1.0;
  c.x0 = x0;
  c.x1 = x1;

  solve_power(x0, y0, toe_slope, c.toe.ln_a, c.toe.b);

  solve_power((1.0 + overshoot_x) - x1, (1.0 + overshoot_y) - y1, shoulder_slope, c.shoulder.ln_a, c.shoulder.b);
  c.shoulder.offset_x = 1.0 + overshoot_x;
  c.shoulder.offset_y = 1.0 + overshoot_y;
  c.shoulder.scale_x = -1.0;
  c.shoulder.scale_y = -1.0;

  // Scale so that W (normalised x = 1) maps to exactly 1.
  const double inv_scale = 1.0 / c.shoulder.eval(1.0);
  for (PowerSegment* s : {&c.toe, &c.middle, &c.shoulder}) {
    s->offset_y *= inv_scale;
    s->scale_y *= inv_scale;
  }
  return c;
}

}  // namespace

OperatorDef hable_operator() {
  OperatorDef d;
  d.name = "hable";
  d.summary = "Uncharted 2 filmic: rational curve with toe and shoulder, white-normalised";
  d.citation = "John Hable, Uncharted 2: HDR Lighting, GDC 2010 (A..F = 0.15, 0.50, 0.10, 0.20, 0.02, 0.30)";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("A", 0.15, 1e-4, 10, "shoulder strength"),
              number_param("B", 0.50, 1e-4, 10, "linear strength"),
              number_param("C", 0.10, 0, 10, "linear angle"),
              number_param("D", 0.20, 1e-4, 10, "toe strength"),
              number_param("E", 0.02, 0, 10, "toe numerator"),
              number_param("F", 0.30, 1e-4, 10, "toe denominator"),
              number_param("exposure_bias", 2.0, 1e-4, 1e4, "input multiplier before the curve"),
              number_param("white", 11.2, 1e-3, 65504, "white point in the curve's domain (after exposure_bias): input white / exposure_bias maps to 1"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    Uncharted2Curve c;
    c.k = {v.number("A"), v.number("B"), v.number("C"), v.number("D"), v.number("E"), v.number("F")};
    c.exposure_bias = v.number("exposure_bias");
    c.white_scale = 1.0 / c.k.partial(v.number("white"));
    return make_curve_evaluator(c, curve_options_from(v));
  };
  return d;
}

OperatorDef hable_piecewise_operator() {
  OperatorDef d;
  d.name = "hable-piecewise";
  d.summary = "Hable's piecewise power curve: power toe, linear middle, mirrored power shoulder";
  d.citation = "John Hable, Filmic Tonemapping with Piecewise Power Curves, filmicworlds.com, 2017";
  d.default_kind = Kind::PerChannel;
  d.params = {number_param("toe_strength", 0.5, 0, 1, "how much the toe darkens (0: none)"),
              number_param("toe_length", 0.5, 0.01, 1, "how far the toe extends, in perceptual units"),
              number_param("shoulder_strength", 2.0, 0, 10, "stops of extra range compressed into the shoulder"),
              number_param("shoulder_length", 0.5, 0.01, 0.99, "how long the shoulder is, as a share of the output"),
              number_param("shoulder_angle", 1.0, 0, 1, "overshoot: how hard the shoulder rolls off"),
              number_param("gamma", 1.0, 0.2, 5, "gamma of the linear section"),
              mode_param(Mode::PerChannel), saturation_param()};
  d.make = [](const ParamValues& v) {
    return make_curve_evaluator(
        make_piecewise(v.number("toe_strength"), v.number("toe_length"), v.number("shoulder_strength"),
                       v.number("shoulder_length"), v.number("shoulder_angle"), v.number("gamma")),
        curve_options_from(v));
  };
  return d;
}

}  // namespace cgtmo::operators
