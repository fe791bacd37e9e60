// color/chromaticities.h against published matrices: Rec.709 -> XYZ (ITU-R BT.709 primaries,
// D65), AP0/AP1 -> XYZ (SMPTE ST 2065-1, Academy S-2014-004), the ACES D60 -> D65 Bradford
// matrix and the ACEScg -> linear sRGB matrix of the ACES reference configs; round trips.
#include <gtest/gtest.h>

#include <array>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/errors.h"

namespace cgtmo::color {
namespace {

using Rows = std::array<std::array<double, 3>, 3>;

void expect_near(const Mat3& a, const Rows& b, double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(a.m[i][j], b[i][j], tol) << "row " << i << " col " << j;
}

TEST(Chromaticities, Rec709ToXyzIsThePublishedMatrix) {
  expect_near(rgb_to_xyz(rec709()),
              {{{0.4123908, 0.3575843, 0.1804808}, {0.2126390, 0.7151687, 0.0721923}, {0.0193308, 0.1191948, 0.9505322}}},
              2e-6);
}

TEST(Chromaticities, AcesPrimariesToXyzArePublished) {
  expect_near(rgb_to_xyz(aces_ap0()),
              {{{0.9525523959, 0.0, 0.0000936786}, {0.3439664498, 0.7281660966, -0.0721325464}, {0.0, 0.0, 1.0088251844}}},
              1e-8);
  expect_near(rgb_to_xyz(aces_ap1()),
              {{{0.6624541811, 0.1340042065, 0.1561876870}, {0.2722287168, 0.6740817658, 0.0536895174},
                {-0.0055746495, 0.0040607335, 1.0103391003}}},
              1e-8);
}

TEST(Chromaticities, BradfordD60ToD65IsTheAcesMatrix) {
  expect_near(bradford(kD60Aces, kD65),
              {{{0.987224, -0.00611327, 0.0159533}, {-0.00759836, 1.00186, 0.00533002}, {0.00307257, -0.00509595, 1.08168}}},
              1e-5);
}

TEST(Chromaticities, BradfordMapsWhiteToWhiteAndInvertsItself) {
  const double a[2] = {0.3457, 0.3585};  // D50
  const Mat3 m = bradford(a, kD65);
  double x = a[0] / a[1], y = 1.0, z = (1 - a[0] - a[1]) / a[1];
  m.apply(x, y, z);
  EXPECT_NEAR(x, kD65[0] / kD65[1], 1e-12);
  EXPECT_NEAR(y, 1.0, 1e-12);
  EXPECT_NEAR(z, (1 - kD65[0] - kD65[1]) / kD65[1], 1e-12);
  expect_near(bradford(kD65, a) * m, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-12);
}

TEST(Chromaticities, AcescgToRec709IsThePublishedMatrix) {
  const Rows published = {{{1.7050509927, -0.6217921206, -0.0832588720},
                           {-0.1302564175, 1.1408047366, -0.0105483190},
                           {-0.0240033568, -0.1289689761, 1.1529723329}}};
  expect_near(to_rec709(aces_ap1()), published, 1e-4);
  // The library's operator matrix (from the reference configs) is the same conversion.
  EXPECT_LT(max_abs_difference(to_rec709(aces_ap1()), ap1_to_rec709()), 1e-4);
}

TEST(Chromaticities, EverySpaceKeepsWhiteWhite) {
  for (const auto& c : {rec709(), aces_ap1(), aces_ap0(), rec2020(), p3_d65(), cie_xyz()}) {
    const Mat3 m = to_rec709(c);
    if (same_chromaticities(c, cie_xyz())) {
      // XYZ is colorimetric: the D65 white's XYZ is Rec.709 white.
      double x = kD65[0] / kD65[1], y = 1.0, z = (1 - kD65[0] - kD65[1]) / kD65[1];
      m.apply(x, y, z);
      EXPECT_NEAR(x, 1.0, 1e-9);
      EXPECT_NEAR(y, 1.0, 1e-9);
      EXPECT_NEAR(z, 1.0, 1e-9);
      continue;
    }
    double r = 1, g = 1, b = 1;
    m.apply(r, g, b);
    EXPECT_NEAR(r, 1.0, 1e-9) << describe(c);
    EXPECT_NEAR(g, 1.0, 1e-9) << describe(c);
    EXPECT_NEAR(b, 1.0, 1e-9) << describe(c);
  }
}

TEST(Chromaticities, RoundTripsThroughXyzAndAp1) {
  expect_near(to_rec709(rec709()), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-12);
  // Rec.709 -> XYZ -> Rec.709 and Rec.709 -> AP1 -> Rec.709.
  expect_near(to_rec709(cie_xyz()) * rgb_to_xyz(rec709()), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 1e-12);
  expect_near(to_rec709(aces_ap1()) * rec709_to_ap1(), {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 2e-4);
  // Same white: AP0 -> Rec.709 equals AP0 -> AP1 -> Rec.709.
  const Mat3 ap0_to_ap1 = rgb_to_xyz(aces_ap1()).inverse() * rgb_to_xyz(aces_ap0());
  EXPECT_LT(max_abs_difference(to_rec709(aces_ap0()), to_rec709(aces_ap1()) * ap0_to_ap1), 1e-12);
}

TEST(Chromaticities, DescribesKnownSetsByName) {
  EXPECT_EQ(describe(aces_ap1()), "ACEScg (AP1) primaries, ACES white (D60)");
  EXPECT_EQ(describe(rec709()), "Rec.709/sRGB primaries, D65 white");
  EXPECT_EQ(describe(cie_xyz()), "CIE XYZ, white E");
  Chromaticities odd = rec709();
  odd.red[0] = 0.6;
  EXPECT_EQ(describe(odd), "primaries R (0.6,0.33) G (0.3,0.6) B (0.15,0.06), D65 white");
}

TEST(Chromaticities, DegenerateSetsAreDataErrors) {
  Chromaticities c = rec709();
  c.green[0] = 0.395;  // on the line from red to blue
  c.green[1] = 0.195;
  EXPECT_THROW(rgb_to_xyz(c), DataError);
  c = rec709();
  c.white[1] = 0.0;
  EXPECT_THROW(rgb_to_xyz(c), DataError);
}

// An EXR attribute holds float32: reading it back must give the published set, exactly, so that
// a pure primary converted by the exact matrix keeps no colour in its other channels.
TEST(Chromaticities, Float32AttributesReadAsThePublishedSet) {
  auto as_float = [](Chromaticities c) {
    for (double* v : {c.red, c.green, c.blue, c.white})
      for (int i = 0; i < 2; ++i) v[i] = double(float(v[i]));
    return c;
  };
  for (auto make : {rec709, aces_ap1, aces_ap0, rec2020, p3_d65, cie_xyz}) {
    const Chromaticities exact = make();
    const Chromaticities stored = as_float(exact);
    const Chromaticities read = published_from_float32(stored);
    EXPECT_EQ(max_abs_difference(to_rec709(read), to_rec709(exact)), 0.0) << describe(exact);
  }
  // The rounding matters: AP1 from its float32 attribute is off by more than float32 can carry.
  EXPECT_GT(max_abs_difference(to_rec709(as_float(aces_ap1())), to_rec709(aces_ap1())), 1e-8);
  // A set that is not published is kept as stored, white included.
  Chromaticities custom = aces_ap1();
  custom.red[0] = 0.7;
  custom.white[0] = 0.31;
  const Chromaticities read = published_from_float32(as_float(custom));
  EXPECT_EQ(read.red[0], double(float(0.7)));
  EXPECT_EQ(read.white[0], double(float(0.31)));
  // Primaries of one set with the white of another: each part is matched on its own.
  Chromaticities mixed = rec2020();
  mixed.white[0] = kD60Aces[0];
  mixed.white[1] = kD60Aces[1];
  const Chromaticities m = published_from_float32(as_float(mixed));
  EXPECT_EQ(m.green[1], 0.797);
  EXPECT_EQ(m.white[0], kD60Aces[0]);
}

}  // namespace
}  // namespace cgtmo::color
