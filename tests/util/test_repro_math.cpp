// util/repro_math: against glibc's long-double functions (x87, 64-bit mantissa: an oracle 11 bits
// finer than the double results, with no CPU-dependent variants), on the arguments that are hard
// for each function: near the reduction boundaries, subnormals, huge and tiny values, and exact cases.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "cgtmo/util/repro_math.h"

namespace repro = cgtmo::repro;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// |got - want| in units of the last place of double at want.
double ulp_error(double got, long double want) {
  if (std::isnan(double(want))) return std::isnan(got) ? 0 : 1e30;
  if (std::isinf(double(want))) return got == double(want) ? 0 : 1e30;
  const double w = double(want);
  const double ulp = w == 0 ? std::numeric_limits<double>::denorm_min()
                            : std::nextafter(std::fabs(w), kInf) - std::fabs(w);
  return double(std::fabs((long double)got - want) / ulp);
}

// Arguments log-spaced over [lo, hi] plus a deterministic random set between them.
std::vector<double> samples(double lo, double hi, int n) {
  std::vector<double> v;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / (n - 1);
    v.push_back(lo + (hi - lo) * t);
    v.push_back(lo + (hi - lo) * u(rng));
  }
  return v;
}
std::vector<double> log_samples(double lo, double hi, int n) {
  std::vector<double> v;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  for (int i = 0; i < n; ++i) v.push_back(std::exp(u(rng)));
  return v;
}

template <class F, class G>
double worst_ulp(const std::vector<double>& xs, F f, G oracle) {
  double worst = 0;
  for (double x : xs) worst = std::max(worst, ulp_error(f(x), oracle((long double)x)));
  return worst;
}

}  // namespace

TEST(ReproMath, ExpWithinTwoUlp) {
  auto xs = samples(-745, 709.7, 20000);
  for (double k = -1074; k <= 1023; k += 1) xs.push_back(k * 0.6931471805599453);  // reduction boundaries
  for (double x : {0.0, -0.0, 1e-300, -1e-300, 0.34657359, -0.34657359, 1.0, 88.72, -708.4}) xs.push_back(x);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::exp(x); }, [](long double x) { return expl(x); }), 2.0);
  EXPECT_EQ(repro::exp(0.0), 1.0);
  EXPECT_EQ(repro::exp(1000.0), kInf);
  EXPECT_EQ(repro::exp(-1000.0), 0.0);
  EXPECT_EQ(repro::exp(-kInf), 0.0);
  EXPECT_TRUE(std::isnan(repro::exp(std::nan(""))));
}

TEST(ReproMath, Exp2ExactOnIntegers) {
  for (int k = -1074; k <= 1023; ++k) ASSERT_EQ(repro::exp2(double(k)), std::ldexp(1.0, k)) << k;
  auto xs = samples(-1074, 1023.9, 20000);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::exp2(x); }, [](long double x) { return exp2l(x); }), 2.0);
  EXPECT_EQ(repro::exp2(1024.0), kInf);
}

TEST(ReproMath, LogFamilyWithinTwoUlp) {
  auto xs = log_samples(1e-308, 1e308, 40000);
  auto near1 = samples(0.5, 2.0, 20000);
  xs.insert(xs.end(), near1.begin(), near1.end());
  for (double x : {std::numeric_limits<double>::denorm_min(), 1e-320, 0.7071067811865476, 0.7071067811865475,
                   1.4142135623730951, 1.0000000000000002, 0.9999999999999999, 65504.0})
    xs.push_back(x);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::log(x); }, [](long double x) { return logl(x); }), 2.0);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::log2(x); }, [](long double x) { return log2l(x); }), 2.0);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::log10(x); }, [](long double x) { return log10l(x); }), 2.0);
  for (int k = -1074; k <= 1023; ++k) ASSERT_EQ(repro::log2(std::ldexp(1.0, k)), double(k)) << k;
  EXPECT_EQ(repro::log(1.0), 0.0);
  EXPECT_EQ(repro::log(0.0), -kInf);
  EXPECT_EQ(repro::log(kInf), kInf);
  EXPECT_TRUE(std::isnan(repro::log(-1.0)));
  EXPECT_TRUE(std::isnan(repro::log10(-1e-300)));
}

TEST(ReproMath, Log1pAccurateNearZero) {
  auto xs = log_samples(1e-300, 1e300, 20000);
  auto neg = samples(-0.999999, 1.0, 20000);
  xs.insert(xs.end(), neg.begin(), neg.end());
  for (double x : {1e-17, -1e-17, 1e-10, 2.220446049250313e-16}) xs.push_back(x);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::log1p(x); }, [](long double x) { return log1pl(x); }), 3.0);
  EXPECT_EQ(repro::log1p(-1.0), -kInf);
  EXPECT_TRUE(std::isnan(repro::log1p(-2.0)));
}

TEST(ReproMath, PowWithinTwoUlpAndExactOnExactCases) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> lx(std::log(1e-30), std::log(1e30)), uy(-8.0, 8.0);
  double worst = 0;
  for (int i = 0; i < 40000; ++i) {
    const double x = std::exp(lx(rng)), y = uy(rng);
    const long double want = powl((long double)x, (long double)y);
    if (!std::isfinite(double(want)) || double(want) == 0) continue;
    worst = std::max(worst, ulp_error(repro::pow(x, y), want));
  }
  EXPECT_LE(worst, 2.0);
  // IEEE special cases, as std::pow.
  const double specials[] = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.5, -0.5, 3.0, -3.0, kInf, -kInf};
  for (double x : specials)
    for (double y : specials) {
      const double want = std::pow(x, y), got = repro::pow(x, y);
      if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << "pow(" << x << ", " << y << ")";
        continue;
      }
      EXPECT_TRUE(ulp_error(got, want) <= 1 && std::signbit(got) == std::signbit(want)) << "pow(" << x << ", " << y << ") = " << got << ", want " << want;
    }
  EXPECT_TRUE(std::isnan(repro::pow(-2.0, 0.5)));
  EXPECT_EQ(repro::pow(std::nan(""), 0.0), 1.0);
  EXPECT_EQ(repro::pow(-8.0, 3.0), -512.0);
  for (int k = -1074; k <= 1023; ++k) ASSERT_EQ(repro::pow(2.0, double(k)), std::ldexp(1.0, k)) << "2^" << k;
  for (int b = 3; b <= 10; ++b)
    for (int k = -10; k <= 10; ++k) EXPECT_LE(ulp_error(repro::pow(double(b), double(k)), powl(b, k)), 1.0) << b << "^" << k;
}

TEST(ReproMath, TrigonometryWithinTwoUlp) {
  auto xs = samples(-1000, 1000, 40000);
  for (int k = -200; k <= 200; ++k) xs.push_back(k * 0.7853981633974483);  // octant boundaries
  for (double x : {1e-300, -1e-300, 1e-8, 3.141592653589793, 1.5707963267948966}) xs.push_back(x);
  auto sin_near = [](double x, long double want) {  // absolute near zeros of the function
    return std::fabs(double(want)) < 1e-6 ? 0.0 : ulp_error(x, want);
  };
  double ws = 0, wc = 0, wt = 0;
  for (double x : xs) {
    ws = std::max(ws, sin_near(repro::sin(x), sinl(x)));
    wc = std::max(wc, sin_near(repro::cos(x), cosl(x)));
    if (std::fabs(double(cosl(x))) > 1e-6) wt = std::max(wt, sin_near(repro::tan(x), tanl(x)));
  }
  EXPECT_LE(ws, 2.0);
  EXPECT_LE(wc, 2.0);
  EXPECT_LE(wt, 3.0);
  EXPECT_EQ(repro::sin(0.0), 0.0);
  EXPECT_EQ(repro::cos(0.0), 1.0);
  EXPECT_TRUE(std::isnan(repro::sin(kInf)));
}

TEST(ReproMath, ArctangentsWithinThreeUlp) {
  auto xs = log_samples(1e-300, 1e300, 20000);
  auto mid = samples(-4, 4, 20000);
  xs.insert(xs.end(), mid.begin(), mid.end());
  for (double x : {0.41421356237309503, 0.41421356237309515, 1.0, -1.0, 2.414213562373095}) xs.push_back(x);
  EXPECT_LE(worst_ulp(xs, [](double x) { return repro::atan(x); }, [](long double x) { return atanl(x); }), 3.0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-10, 10);
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    const double y = u(rng), x = u(rng);
    worst = std::max(worst, ulp_error(repro::atan2(y, x), atan2l(y, x)));
  }
  EXPECT_LE(worst, 3.0);
  const double specials[] = {0.0, -0.0, 1.0, -1.0, kInf, -kInf};
  for (double y : specials)
    for (double x : specials) {
      const double want = std::atan2(y, x), got = repro::atan2(y, x);
      EXPECT_TRUE(ulp_error(got, want) <= 1 && std::signbit(got) == std::signbit(want)) << "atan2(" << y << ", " << x << ")";
    }
}

TEST(ReproMath, HypotAndErfc) {
  EXPECT_EQ(repro::hypot(3.0, 4.0), 5.0);
  EXPECT_EQ(repro::hypot(1e300, 1e300), std::sqrt(2.0) * 1e300);
  EXPECT_EQ(repro::hypot(-kInf, std::nan("")), kInf);
  double worst = 0;
  for (double x : samples(-6, 27, 20000)) {
    const long double want = erfcl(x);
    // erfc is 1 - erf below 2.5: an absolute error of a few 1e-16 there; beyond, relative (normal results).
    if (double(want) < 1e-300) continue;
    const double err = x < 2.5 ? double(std::fabs((long double)repro::erfc(x) - want)) / 2e-15 : ulp_error(repro::erfc(x), want) / 4;
    worst = std::max(worst, err);
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_EQ(repro::erfc(30.0), 0.0);
  EXPECT_EQ(repro::erfc(-30.0), 2.0);
}

// The point of the module: values that are bit-identical to a recorded set, whatever the CPU.
// The digest is of the functions over a fixed grid; a change to the module's arithmetic changes it
// (then re-record it with the new value this test prints, after checking the accuracy tests).
TEST(ReproMath, DigestIsFixed) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    h = (h ^ b) * 1099511628211ull;
  };
  for (int i = 0; i < 4000; ++i) {
    const double x = 1e-3 + i * 0.0173;
    mix(repro::exp(x - 30)); mix(repro::exp2(x - 30)); mix(repro::log(x)); mix(repro::log2(x)); mix(repro::log10(x));
    mix(repro::log1p(x)); mix(repro::pow(x, 2.2)); mix(repro::pow(x, 1.0 / 2.4)); mix(repro::sin(x)); mix(repro::cos(x));
    mix(repro::tan(x)); mix(repro::atan(x - 30)); mix(repro::atan2(x - 30, 3.0)); mix(repro::hypot(x, 1.5)); mix(repro::erfc(x / 10 - 3));
  }
  EXPECT_EQ(h, 0xdce05b9fad2d08a4ull) << std::hex << "digest 0x" << h;
}
