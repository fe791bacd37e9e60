// AgX base (Wrensch's minimal AgX constants). The matrices are checked against the published inset
// and the published outset (its inverse, given to 15 digits in the source); the curve against the
// 6th-order polynomial written here in Horner form, at the ends of the log2 range and in between.
// Order as implemented (docs/operators.md): inset, log2 encode, polynomial, 2.2 power, outset.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "cgtmo/operators/registry.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

using M3 = std::array<std::array<double, 3>, 3>;
// Rows (the GLSL source lists them column by column).
const M3 kInset = {{{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
                    {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
                    {0.0423756549057051, 0.0784336, 0.879142973793104}}};
const M3 kOutset = {{{1.19687900512017, -0.0980208811401368, -0.0990297440797205},
                     {-0.0528968517574562, 1.15190312990417, -0.0989611768448433},
                     {-0.0529716355144438, -0.0980434501171241, 1.15107367264116}}};
constexpr double kMinEv = -12.47393, kMaxEv = 4.026069;

double sigmoid(double n) {  // Horner form of 15.5 n^6 - 40.14 n^5 + 31.96 n^4 - 6.868 n^3 + 0.4298 n^2 + 0.1191 n - 0.00232
  return ((((((15.5 * n - 40.14) * n + 31.96) * n - 6.868) * n + 0.4298) * n + 0.1191) * n) - 0.00232;
}

double encode(double v) {
  const double e = std::min(kMaxEv, std::max(kMinEv, std::log2(v)));
  return (e - kMinEv) / (kMaxEv - kMinEv);
}

std::array<double, 3> reference(std::array<double, 3> c) {
  std::array<double, 3> v{}, out{};
  for (int i = 0; i < 3; ++i) v[i] = kInset[i][0] * c[0] + kInset[i][1] * c[1] + kInset[i][2] * c[2];
  for (double& x : v) x = std::pow(std::max(0.0, sigmoid(encode(x))), 2.2);
  for (int i = 0; i < 3; ++i) out[i] = kOutset[i][0] * v[0] + kOutset[i][1] * v[1] + kOutset[i][2] * v[2];
  for (double& x : out) x = std::min(1.0, std::max(0.0, x));
  return out;
}

TEST(Agx, MatricesAreThePublishedInsetAndOutset) {
  auto ev = make_evaluator(find_operator("agx"), {}, nullptr);
  ASSERT_TRUE(ev->input_matrix && ev->output_matrix);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(ev->input_matrix->m[i][j], kInset[i][j], 1e-12);
      EXPECT_NEAR(ev->output_matrix->m[i][j], kOutset[i][j], 1e-9) << i << j;
    }
}

TEST(Agx, PolynomialAtTheEndsOfTheLog2Range) {
  EXPECT_NEAR(sigmoid(0), -0.00232, 1e-12);  // below 0: clamped to 0
  EXPECT_NEAR(sigmoid(1), 0.99858, 1e-9);    // sum of the coefficients
  auto ev = make_evaluator(find_operator("agx"), {}, nullptr);
  EXPECT_EQ(ev->curve(0.0), 0.0);
  EXPECT_EQ(ev->curve(std::exp2(kMinEv - 1)), 0.0);
  EXPECT_NEAR(ev->curve(std::exp2(kMaxEv + 1)), std::pow(0.99858, 2.2), 1e-6);
  EXPECT_NEAR(ev->curve(65504.0), std::pow(0.99858, 2.2), 1e-6);
  // 0.18 sits 10 stops above the bottom of the 16.5-stop range.
  EXPECT_NEAR(ev->curve(0.18), std::pow(sigmoid(10.0 / 16.499999), 2.2), 2e-6);
}

TEST(Agx, PixelsMatchTheReference) {
  const std::array<double, 3> colours[] = {{0.18, 0.18, 0.18}, {1, 0, 0},   {0, 1, 0},       {0, 0, 1},
                                           {0.5, 0.25, 0.1},   {4, 2, 1},   {0.01, 0.02, 0.03}, {65504, 65504, 65504},
                                           {0, 0, 0}};
  for (const auto& c : colours) {
    const RGB out = run1("agx", {float(c[0]), float(c[1]), float(c[2])});
    const auto ref = reference(c);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], ref[k], 5e-6) << c[0] << "," << c[1] << "," << c[2] << " ch " << k;
  }
}

// Wrensch's own order: outset on the encoded sigmoid output, then the 2.2 power. cgtmo swaps the
// two (docs/operators.md) to stay "matrix, per-channel curve, matrix"; this records how far apart
// the two are: nothing on greys, up to about 0.07 on pure primaries.
std::array<double, 3> wrensch_order(std::array<double, 3> c) {
  std::array<double, 3> v{}, out{};
  for (int i = 0; i < 3; ++i) v[i] = kInset[i][0] * c[0] + kInset[i][1] * c[1] + kInset[i][2] * c[2];
  for (double& x : v) x = sigmoid(encode(x));
  for (int i = 0; i < 3; ++i) out[i] = kOutset[i][0] * v[0] + kOutset[i][1] * v[1] + kOutset[i][2] * v[2];
  for (double& x : out) x = std::min(1.0, std::pow(std::max(0.0, x), 2.2));
  return out;
}

TEST(Agx, DeviationFromWrenschsOrderIsBounded) {
  auto max_diff = [](std::array<double, 3> c) {
    const RGB out = run1("agx", {float(c[0]), float(c[1]), float(c[2])});
    const auto w = wrensch_order(c);
    double d = 0;
    for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(out[k] - w[k]));
    return d;
  };
  for (double g : {0.01, 0.18, 1.0, 16.0}) EXPECT_LT(max_diff({g, g, g}), 5e-4) << g;
  const double red = max_diff({1, 0, 0}), green = max_diff({0, 1, 0}), blue = max_diff({0, 0, 1});
  EXPECT_NEAR(red, 0.0718, 2e-3);
  EXPECT_NEAR(green, 0.0366, 2e-3);
  EXPECT_NEAR(blue, 0.0361, 2e-3);
}

}  // namespace
}  // namespace cgtmo::operators::test
