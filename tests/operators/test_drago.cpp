// Drago et al. 2003 in the paper's log10 form, against the implementation's natural-log form:
//   Ld = (ld_max / 100) / log10(1 + M) * log10(1 + L) / log10(2 + 8 (L / M)^(ln b / ln 0.5)),
// with L = Lw / lw_a and M = lw_max / lw_a.
#include <gtest/gtest.h>

#include <cmath>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

double drago_log10(double lw, double b, double ld_max, double lw_max, double lw_a) {
  const double l = lw / lw_a, m = lw_max / lw_a;
  return (ld_max / 100.0) / std::log10(1 + m) * std::log10(1 + l) /
         std::log10(2 + 8 * std::pow(l / m, std::log(b) / std::log(0.5)));
}

Params given(double b, double ld_max, double lw_max, double lw_a) {
  return {{"b", std::to_string(b)}, {"ld_max", std::to_string(ld_max)},
          {"lw_max", std::to_string(lw_max)}, {"lw_a", std::to_string(lw_a)}};
}

TEST(Drago, MatchesTheLog10FormOnGreys) {
  for (double b : {0.7, 0.85, 0.95})
    for (double x : {0.001, 0.05, 0.5, 3.0, 40.0})
      EXPECT_NEAR(grey("drago", x, given(b, 100, 100, 0.5)), drago_log10(x, b, 100, 100, 0.5), 2e-6)
          << "b " << b << " x " << x;
}

TEST(Drago, SceneMaximumMapsToLdMaxOver100) {
  EXPECT_NEAR(grey("drago", 100.0, given(0.85, 100, 100, 0.5)), 1.0, 1e-6);
  EXPECT_NEAR(grey("drago", 250.0, given(0.7, 100, 250, 3.0)), 1.0, 1e-6);
  EXPECT_NEAR(grey("drago", 100.0, given(0.85, 80, 100, 0.5)), 0.8, 1e-6);
  EXPECT_EQ(grey("drago", 400.0, given(0.85, 100, 100, 0.5)), 1.0);  // above lw_max: clamped
}

TEST(Drago, BiasOneIsAPureLogarithm) {
  // ln 1 / ln 0.5 = 0: the denominator is log10(10) = 1, Ld = log(1 + L) / log(1 + M).
  for (double x : {0.01, 1.0, 20.0})
    EXPECT_NEAR(grey("drago", x, given(1.0, 100, 100, 2.0)), std::log1p(x / 2.0) / std::log1p(50.0), 2e-6) << x;
}

TEST(Drago, DefaultsComeFromTheImage) {
  // Greys 100, 1 and 0.01: lw_max = 100, lw_a = exp(mean ln(1e-4 + L)).
  const double lw_a = std::exp((std::log(100.0001) + std::log(1.0001) + std::log(0.0101)) / 3.0);
  const auto out = run("drago", {{100.f, 100.f, 100.f}, {1.f, 1.f, 1.f}, {0.01f, 0.01f, 0.01f}});
  EXPECT_NEAR(out[0][0], 1.0, 1e-6);
  EXPECT_NEAR(out[1][0], drago_log10(1.0, 0.85, 100, 100, lw_a), 2e-6);
  EXPECT_NEAR(out[2][0], drago_log10(0.01, 0.85, 100, 100, lw_a), 2e-6);
}

TEST(Drago, LuminanceModeKeepsChromaticity) {
  const RGB out = run1("drago", {0.4f, 0.2f, 0.1f}, given(0.85, 100, 100, 0.5));
  const double l = 0.2126 * 0.4 + 0.7152 * 0.2 + 0.0722 * 0.1;
  const double s = drago_log10(l, 0.85, 100, 100, 0.5) / l;
  EXPECT_NEAR(out[0], 0.4 * s, 2e-6);
  EXPECT_NEAR(out[1], 0.2 * s, 2e-6);
  EXPECT_NEAR(out[2], 0.1 * s, 2e-6);
}

TEST(Drago, TinyMaximumOverAdaptationStaysFinite) {
  // lw_max / lw_a = 1e-30: log10(1 + M') is 0 in double; the implementation's log1p form is not.
  // In that limit ln(1 + L') ~ L' and log10(1 + M') ~ M' / ln 10, so Ld -> r ln 10 / ln(2 + 8 r^e)
  // with r = Lw / lw_max and e = ln b / ln 0.5.
  const double e = std::log(0.85) / std::log(0.5);
  for (double r : {0.01, 0.5, 1.0}) {
    const double ref = r * std::log(10.0) / std::log(2 + 8 * std::pow(r, e));
    EXPECT_NEAR(grey("drago", r, given(0.85, 100, 1, 1e30)), ref, 2e-6) << r;
  }
  EXPECT_EQ(grey("drago", 0.0, given(0.85, 100, 1, 1e30)), 0.0);
}

}  // namespace
}  // namespace cgtmo::operators::test
