#include "cgtmo/util/repro_math.h"

#include <cmath>
#include <limits>
#include <utility>

// Only +, -, *, /, sqrt and exact bit operations (frexp, ldexp, nearbyint, copysign) below: their
// results are fixed by IEEE-754, so these functions give the same bits on every CPU. The series are
// Taylor series of the reduced argument, long enough that their truncation is below 1e-17.
namespace cgtmo::repro {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ln 2 split so that k * kLn2Hi is exact for |k| < 2^11 (the high part has 42 significant bits).
constexpr double kLn2Hi = 0x1.62e42fefa3800p-1;
constexpr double kLn2Lo = 0x1.ef35793c76730p-45;
constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kInvLn10 = 0x1.bcb7b1526e50ep-2;
constexpr double kLog10of2Hi = 0x1.34413509f7800p-2;
constexpr double kLog10of2Lo = 0x1.fef311f12b358p-46;
// pi/2 in three parts of 33 significant bits (k * part exact for |k| < 2^20), and pi/2, pi/4, pi
// as a double plus the rest.
constexpr double kPio2Part1 = 0x1.921fb54400000p+0;
constexpr double kPio2Part2 = 0x1.0b4611a600000p-34;
constexpr double kPio2Part3 = 0x1.3198a2e037073p-69;
constexpr double kPio2Hi = 0x1.921fb54442d18p+0, kPio2Lo = 0x1.1a62633145c07p-54;
constexpr double kPio4Hi = 0x1.921fb54442d18p-1, kPio4Lo = 0x1.1a62633145c07p-55;
constexpr double kPiHi = 0x1.921fb54442d18p+1, kPiLo = 0x1.1a62633145c07p-53;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kTanPiOver8 = 0x1.a827999fcef32p-2;
constexpr double kSqrtHalf = 0x1.6a09e667f3bcdp-1;
constexpr double kInvSqrtPi = 0x1.20dd750429b6dp-1;

// 1/n! for n = 0..20, computed once at compile time.
struct InverseFactorials {
  double v[21] = {};
  constexpr InverseFactorials() {
    double f = 1;
    for (int n = 0; n <= 20; ++n) {
      if (n > 1) f *= n;  // exact up to 18!, then rounded once per step
      v[n] = 1.0 / f;
    }
  }
};
constexpr InverseFactorials kInvFact;
constexpr double inverse_factorial(int n) { return kInvFact.v[n]; }

// e^r for |r| <= 0.35: Taylor to r^13 (the next term is below 5e-18).
double exp_kernel(double r) {
  double p = inverse_factorial(13);
  for (int n = 12; n >= 0; --n) p = p * r + inverse_factorial(n);
  return p;
}

// ln(m) for m in [sqrt(1/2), sqrt(2)): with f = m - 1 and s = f / (2 + f), ln(m) = 2 atanh(s)
// = f - (f^2/2 - s (f^2/2 + R)), R = sum_k 2 s^(2k) / (2k + 1); |s| <= 0.172, so k <= 11 suffices.
double log_kernel(double m) {
  const double f = m - 1.0;  // exact
  const double s = f / (2.0 + f);
  const double z = s * s;
  double r = 2.0 / 23.0;
  for (int k = 10; k >= 1; --k) r = r * z + 2.0 / (2 * k + 1);
  r *= z;
  const double half_f2 = 0.5 * f * f;
  return f - (half_f2 - s * (half_f2 + r));
}

// x = m 2^e with m in [sqrt(1/2), sqrt(2)); x finite and > 0.
double split(double x, int& e) {
  double m = std::frexp(x, &e);
  if (m < kSqrtHalf) {
    m *= 2;
    --e;
  }
  return m;
}

// sin and cos of |r| <= pi/4 (plus rounding): Taylor to r^19 and r^20.
double sin_kernel(double r) {
  const double z = r * r;
  double p = -inverse_factorial(19);
  for (int n = 17; n >= 3; n -= 2) p = p * z + ((n / 2) % 2 ? -inverse_factorial(n) : inverse_factorial(n));
  return r + r * z * p;
}
double cos_kernel(double r) {
  const double z = r * r;
  double p = inverse_factorial(20);
  for (int n = 18; n >= 2; n -= 2) p = p * z + ((n / 2) % 2 ? -inverse_factorial(n) : inverse_factorial(n));
  return 1.0 + z * p;
}

// x = k pi/2 + r, |r| <= pi/4 (for |x| below about 1e6; beyond, r loses accuracy but not
// reproducibility). Returns k mod 4.
int reduce_quarter_turns(double x, double& r) {
  const double k = std::nearbyint(x * kTwoOverPi);
  r = ((x - k * kPio2Part1) - k * kPio2Part2) - k * kPio2Part3;
  const double q = k - 4.0 * std::floor(k * 0.25);
  return int(q);
}

// atan(u) for |u| <= tan(pi/8) (0.4142): Taylor to u^47 (the next term is below 1e-19).
double atan_kernel(double u) {
  const double z = u * u;
  double p = -1.0 / 47.0;
  for (int n = 45; n >= 3; n -= 2) p = p * z + ((n / 2) % 2 ? -1.0 / n : 1.0 / n);
  return u + u * z * p;
}

bool is_odd_integer(double y) {
  if (std::fabs(y) >= 0x1p53) return false;  // every such double is even
  return std::nearbyint(y) == y && std::fmod(y, 2.0) != 0.0;
}

// A value carried as hi + lo, |lo| <= ulp(hi) / 2.
struct DoubleDouble {
  double hi, lo;
};

DoubleDouble two_sum(double a, double b) {  // exact: a + b = hi + lo
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Exact a * b = hi + lo without FMA (Dekker): each factor split into two 26-bit halves.
DoubleDouble two_product(double a, double b) {
  constexpr double kSplit = 134217729.0;  // 2^27 + 1
  const double p = a * b;
  const double ca = kSplit * a, cb = kSplit * b;
  const double ah = ca - (ca - a), al = a - ah;
  const double bh = cb - (cb - b), bl = b - bh;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

// ln x (x finite, > 0) to about 2^-100 relative: ln m = 2 atanh(s) with s = f / (2 + f) carried
// in double-double, plus e ln 2.
DoubleDouble log_double_double(double x) {
  int e = 0;
  const double m = split(x, e);
  const double f = m - 1.0;  // exact
  const DoubleDouble d = two_sum(2.0, f);
  const double sh = f / d.hi;
  const DoubleDouble q = two_product(sh, d.hi);
  const double sl = (((f - q.hi) - q.lo) - sh * d.lo) / d.hi;
  const double z = sh * sh;
  double r = 2.0 / 23.0;
  for (int k = 10; k >= 1; --k) r = r * z + 2.0 / (2 * k + 1);
  const double tail = sh * z * r;  // 2 s^3 / 3 + 2 s^5 / 5 + ...
  const DoubleDouble a = two_sum(e * kLn2Hi, 2.0 * sh);
  const DoubleDouble b = two_sum(a.hi, a.lo + (e * kLn2Lo + 2.0 * sl + tail));
  return b;
}

// e^(hi + lo) for |hi + lo| below about 746, |lo| <= ulp(hi).
double exp_double_double(double hi, double lo) {
  const double k = std::nearbyint(hi * kInvLn2);
  const double r = ((hi - k * kLn2Hi) - k * kLn2Lo) + lo;
  return std::ldexp(exp_kernel(r), int(k));
}

// e^(-x^2) with x^2 carried exactly (its rounding would cost |x|^2 ulps).
double exp_of_minus_square(double x) {
  const DoubleDouble sq = two_product(x, x);
  return exp_double_double(-sq.hi, -sq.lo);
}

// erf(x) for 0 <= x <= 2.5 by the series of positive terms
// erf(x) = 2/sqrt(pi) e^(-x^2) sum_n 2^n x^(2n+1) / (1 * 3 * ... * (2n+1)).
double erf_series(double x) {
  const double x2 = x * x;
  double term = x, sum = x;
  for (int n = 1; n < 200 && term > sum * 1e-18; ++n) {
    term *= 2.0 * x2 / (2 * n + 1);
    sum += term;
  }
  return 2.0 * kInvSqrtPi * exp_of_minus_square(x) * sum;
}

// erfc(x) for x >= 2.5 by its continued fraction
// e^(-x^2)/sqrt(pi) / (x + (1/2) / (x + 1 / (x + (3/2) / (x + 2 / (x + ...))))), 80 levels.
double erfc_fraction(double x) {
  double k = x;
  for (int n = 80; n >= 1; --n) k = x + 0.5 * n / k;
  return kInvSqrtPi * exp_of_minus_square(x) / k;
}

}  // namespace

double exp(double x) {
  if (x != x) return x;
  if (x > 709.782712893384) return kInf;
  if (x < -745.1332191019412) return 0.0;
  const double k = std::nearbyint(x * kInvLn2);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  return std::ldexp(exp_kernel(r), int(k));
}

double exp2(double x) {
  if (x != x) return x;
  if (x >= 1024.0) return kInf;
  if (x < -1075.0) return 0.0;
  const double k = std::nearbyint(x);
  const double r = x - k;  // exact, |r| <= 1/2
  return std::ldexp(exp_kernel(r * kLn2Hi + r * kLn2Lo), int(k));
}

double log(double x) {
  if (x != x) return x;
  if (x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return kInf;
  int e = 0;
  const double m = split(x, e);
  return e * kLn2Hi + (log_kernel(m) + e * kLn2Lo);
}

double log2(double x) {
  if (x != x) return x;
  if (x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return kInf;
  int e = 0;
  const double m = split(x, e);
  return double(e) + log_kernel(m) * kInvLn2;
}

double log10(double x) {
  if (x != x) return x;
  if (x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return kInf;
  int e = 0;
  const double m = split(x, e);
  return e * kLog10of2Hi + (log_kernel(m) * kInvLn10 + e * kLog10of2Lo);
}

double log1p(double x) {
  if (x != x || x == kInf) return x;
  if (x < -1.0) return kNaN;
  if (x == -1.0) return -kInf;
  const double u = 1.0 + x;
  if (u == 1.0) return x;
  // u - 1 is exact; the ratio corrects the rounding of 1 + x.
  return log(u) * (x / (u - 1.0));
}

double pow(double x, double y) {
  if (y == 0.0 || x == 1.0) return 1.0;
  if (x != x || y != y) return kNaN;
  if (y == 1.0) return x;
  const bool odd = is_odd_integer(y);
  if (std::isinf(y)) {
    const double a = std::fabs(x);
    if (a == 1.0) return 1.0;
    return (a > 1.0) == (y > 0) ? kInf : 0.0;
  }
  if (x == 0.0) return y > 0 ? (odd ? x : 0.0) : (odd ? std::copysign(kInf, x) : kInf);
  if (std::isinf(x)) {
    const double mag = y > 0 ? kInf : 0.0;
    return x < 0 && odd ? -mag : mag;
  }
  if (x < 0.0) {
    if (std::nearbyint(y) != y) return kNaN;
    const double m = pow(-x, y);
    return odd ? -m : m;
  }
  if (y == 2.0) return x * x;
  if (y == 0.5) return std::sqrt(x);
  // e^(y ln x) with y ln x carried in double-double, so that the result's error does not grow with
  // |y ln x| (pow(2, 3) is 8 exactly).
  const DoubleDouble l = log_double_double(x);
  const double t = y * l.hi;
  if (t > 710.0) return kInf;
  if (t < -746.0) return 0.0;
  const DoubleDouble p = std::fabs(y) < 0x1p995 ? two_product(y, l.hi) : DoubleDouble{t, 0.0};
  return exp_double_double(p.hi, p.lo + y * l.lo);
}

double sin(double x) {
  if (!std::isfinite(x)) return kNaN;
  double r = 0;
  switch (reduce_quarter_turns(x, r)) {
    case 0: return sin_kernel(r);
    case 1: return cos_kernel(r);
    case 2: return -sin_kernel(r);
    default: return -cos_kernel(r);
  }
}

double cos(double x) {
  if (!std::isfinite(x)) return kNaN;
  double r = 0;
  switch (reduce_quarter_turns(x, r)) {
    case 0: return cos_kernel(r);
    case 1: return -sin_kernel(r);
    case 2: return -cos_kernel(r);
    default: return sin_kernel(r);
  }
}

double tan(double x) {
  if (!std::isfinite(x)) return kNaN;
  double r = 0;
  const int q = reduce_quarter_turns(x, r);
  const double s = sin_kernel(r), c = cos_kernel(r);
  return q % 2 == 0 ? s / c : -c / s;
}

double atan(double x) {
  if (x != x) return x;
  const double a = std::fabs(x);
  double t = 0;
  if (a > 1.0) {  // atan(a) = pi/2 - atan(1/a)
    const double inv = 1.0 / a;
    const double u = inv > kTanPiOver8 ? (inv - 1.0) / (inv + 1.0) : inv;
    const double inner = inv > kTanPiOver8 ? (kPio4Hi + (kPio4Lo + atan_kernel(u))) : atan_kernel(u);
    t = kPio2Hi + (kPio2Lo - inner);
  } else if (a > kTanPiOver8) {  // atan(a) = pi/4 + atan((a - 1) / (a + 1))
    t = kPio4Hi + (kPio4Lo + atan_kernel((a - 1.0) / (a + 1.0)));
  } else {
    t = atan_kernel(a);
  }
  return std::copysign(t, x);
}

double atan2(double y, double x) {
  if (x != x || y != y) return kNaN;
  const double pi = kPiHi + kPiLo, pio2 = kPio2Hi + kPio2Lo;
  if (y == 0.0) return std::signbit(x) ? std::copysign(pi, y) : y;
  if (x == 0.0) return std::copysign(pio2, y);
  if (std::isinf(x)) {
    if (std::isinf(y)) return std::copysign(x > 0 ? kPio4Hi + kPio4Lo : 3.0 * kPio4Hi + 3.0 * kPio4Lo, y);
    return x > 0 ? std::copysign(0.0, y) : std::copysign(pi, y);
  }
  if (std::isinf(y)) return std::copysign(pio2, y);
  const double a = atan(std::fabs(y / x));
  return std::copysign(x > 0 ? a : kPiHi + (kPiLo - a), y);
}

double hypot(double x, double y) {
  if (std::isinf(x) || std::isinf(y)) return kInf;
  if (x != x || y != y) return kNaN;
  double a = std::fabs(x), b = std::fabs(y);
  if (a < b) std::swap(a, b);
  if (a == 0.0) return 0.0;
  const double r = b / a;
  return a * std::sqrt(1.0 + r * r);
}

double erfc(double x) {
  if (x != x) return x;
  if (x < 0.0) return 2.0 - erfc(-x);
  if (x > 27.3) return 0.0;  // below the smallest double
  if (x < 2.5) return 1.0 - erf_series(x);
  return erfc_fraction(x);
}

}  // namespace cgtmo::repro
