#pragma once
// Elementary functions that give the same bits on every x86-64 CPU.
//
// glibc picks its exp, log, pow, sin, ... by CPU feature at load time (FMA, AVX2), and the variants
// differ in the last bit; a LUT or a report written through them then differs between machines in
// its 7th digit. These are built from +, -, *, / and sqrt only (IEEE-754 rounds those the same
// everywhere), in double, in a file compiled without FMA contraction (the whole library is built
// with -ffp-contract=off), so a value written to a committed file depends on its inputs alone.
// Accuracy: within a few units in the last place of double (tests/util/test_repro_math.cpp checks
// them against long-double libm: pow within 2 over |y ln x| up to 550).
//
// Every transcendental function the library calls comes from here (tests/util/check_repro_math.py
// fails on a libm call in src/ or apps/). The float overloads evaluate in double and round once.
#include <type_traits>

namespace cgtmo::repro {

double exp(double x);
double exp2(double x);
double log(double x);
double log2(double x);
double log10(double x);
double log1p(double x);
double pow(double x, double y);
double sin(double x);
double cos(double x);
double tan(double x);
double atan(double x);
double atan2(double y, double x);
double hypot(double x, double y);
double erfc(double x);

// Integer arguments evaluate in double (as std:: does), without ambiguity between the overloads.
#define CGTMO_REPRO_INTEGRAL_OVERLOAD(f) \
  template <class I, std::enable_if_t<std::is_integral_v<I>, int> = 0> \
  double f(I x) { return f(double(x)); }
CGTMO_REPRO_INTEGRAL_OVERLOAD(exp)
CGTMO_REPRO_INTEGRAL_OVERLOAD(exp2)
CGTMO_REPRO_INTEGRAL_OVERLOAD(log)
CGTMO_REPRO_INTEGRAL_OVERLOAD(log2)
CGTMO_REPRO_INTEGRAL_OVERLOAD(log10)
CGTMO_REPRO_INTEGRAL_OVERLOAD(log1p)
CGTMO_REPRO_INTEGRAL_OVERLOAD(sin)
CGTMO_REPRO_INTEGRAL_OVERLOAD(cos)
CGTMO_REPRO_INTEGRAL_OVERLOAD(tan)
CGTMO_REPRO_INTEGRAL_OVERLOAD(atan)
#undef CGTMO_REPRO_INTEGRAL_OVERLOAD

inline float exp(float x) { return float(exp(double(x))); }
inline float exp2(float x) { return float(exp2(double(x))); }
inline float log(float x) { return float(log(double(x))); }
inline float log2(float x) { return float(log2(double(x))); }
inline float log10(float x) { return float(log10(double(x))); }
inline float log1p(float x) { return float(log1p(double(x))); }

}  // namespace cgtmo::repro
