// Mat3: product, inverse and application against hand values; the Rec.709 -> AP1 matrix against
// one derived here from the published primaries, white points and the Bradford cone matrix.
#include <gtest/gtest.h>

#include "cgtmo/color/matrix.h"

namespace cgtmo::color {
namespace {

Mat3 make(std::array<std::array<double, 3>, 3> rows) {
  Mat3 m;
  m.m = rows;
  return m;
}

void expect_near(const Mat3& a, const std::array<std::array<double, 3>, 3>& b, double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b[i][j], tol) << "row " << i << " col " << j;
}

const Mat3 kA = make({{{1, 2, 0}, {0, 1, 3}, {4, 0, 1}}});
const Mat3 kB = make({{{2, 0, 1}, {1, 3, 0}, {0, 1, 2}}});

TEST(Mat3, ProductByHand) {
  expect_near(kA * kB, {{{4, 6, 1}, {1, 6, 6}, {8, 1, 6}}}, 0);
  expect_near(kB * kA, {{{6, 4, 1}, {1, 5, 9}, {8, 1, 5}}}, 0);
}

TEST(Mat3, ApplyReadsEveryComponentOnEveryRow) {
  // Hill's ACES input matrix on (1, 2, 3), by hand. The seed guide's mul used v[1] for v[0] on
  // rows two and three and would give 2.01566 and 2.83777 there.
  const Mat3 hill = make({{{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}}});
  double r = 1, g = 2, b = 3;
  hill.apply(r, g, b);
  EXPECT_NEAR(r, 1.45104, 1e-12);
  EXPECT_NEAR(g, 1.93966, 1e-12);
  EXPECT_NEAR(b, 2.80937, 1e-12);
  float x = 1, y = 0, z = 0;  // pure red: the first column
  kA.apply(x, y, z);
  EXPECT_EQ(x, 1.f);
  EXPECT_EQ(y, 0.f);
  EXPECT_EQ(z, 4.f);
}

TEST(Mat3, ProductComposesApplications) {
  double r1 = 0.3, g1 = -1.2, b1 = 2.5, r2 = r1, g2 = g1, b2 = b1;
  kB.apply(r1, g1, b1);
  kA.apply(r1, g1, b1);     // A (B v)
  (kA * kB).apply(r2, g2, b2);  // (A B) v
  EXPECT_NEAR(r1, r2, 1e-12);
  EXPECT_NEAR(g1, g2, 1e-12);
  EXPECT_NEAR(b1, b2, 1e-12);
}

TEST(Mat3, InverseByHand) {
  // det A = 25; inverse = adjugate / 25, cofactors worked out by hand.
  expect_near(kA.inverse(), {{{1 / 25., -2 / 25., 6 / 25.}, {12 / 25., 1 / 25., -3 / 25.}, {-4 / 25., 8 / 25., 1 / 25.}}}, 1e-15);
  expect_near(make({{{2, 0, 0}, {0, 4, 0}, {0, 0, 8}}}).inverse(), {{{0.5, 0, 0}, {0, 0.25, 0}, {0, 0, 0.125}}}, 0);
  expect_near(make({{{1, 2, 0}, {0, 1, 0}, {0, 0, 1}}}).inverse(), {{{1, -2, 0}, {0, 1, 0}, {0, 0, 1}}}, 0);
  expect_near(kA * kA.inverse(), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-15);
}

// RGB -> XYZ from chromaticities (x, y) of R, G, B and white (the usual normalised primary matrix).
Mat3 rgb_to_xyz(const double p[4][2]) {
  Mat3 prim;
  for (int c = 0; c < 3; ++c) {
    prim.m[0][c] = p[c][0] / p[c][1];
    prim.m[1][c] = 1.0;
    prim.m[2][c] = (1 - p[c][0] - p[c][1]) / p[c][1];
  }
  const double w[3] = {p[3][0] / p[3][1], 1.0, (1 - p[3][0] - p[3][1]) / p[3][1]};
  double s[3] = {w[0], w[1], w[2]};
  prim.inverse().apply(s[0], s[1], s[2]);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) prim.m[i][c] *= s[c];
  return prim;
}

TEST(Mat3, Rec709ToAp1MatchesADerivationFromPrimaries) {
  const double srgb[4][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}};
  const double ap1[4][2] = {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, {0.32168, 0.33767}};
  const Mat3 bradford = make({{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}});
  auto white_xyz = [](double x, double y) { return std::array<double, 3>{x / y, 1.0, (1 - x - y) / y}; };
  auto src = white_xyz(0.3127, 0.3290), dst = white_xyz(0.32168, 0.33767);
  bradford.apply(src[0], src[1], src[2]);
  bradford.apply(dst[0], dst[1], dst[2]);
  const Mat3 gain = make({{{dst[0] / src[0], 0, 0}, {0, dst[1] / src[1], 0}, {0, 0, dst[2] / src[2]}}});
  const Mat3 cat = bradford.inverse() * gain * bradford;
  const Mat3 derived = rgb_to_xyz(ap1).inverse() * cat * rgb_to_xyz(srgb);
  expect_near(rec709_to_ap1(), derived.m, 2e-5);
  // White stays white, and the inverse undoes it.
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(rec709_to_ap1().m[i][0] + rec709_to_ap1().m[i][1] + rec709_to_ap1().m[i][2], 1.0, 1e-5);
  expect_near(ap1_to_rec709() * rec709_to_ap1(), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-12);
}

}  // namespace
}  // namespace cgtmo::color
