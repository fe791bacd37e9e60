// color/input_space.h: which space a file is taken to be in, the conversion OCIO gives a named
// space against the one derived from chromaticities, the disagreement warning, and what apply()
// leaves alone (alpha, non-finite pixels).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "cgtmo/color/input_space.h"
#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"

namespace cgtmo::color {
namespace {

const std::string kShipped = std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio";
const std::string kBlender = "/usr/share/blender/datafiles/colormanagement/config.ocio";

TEST(InputSpace, DefaultIsNothingToDo) {
  EXPECT_TRUE(InputSpace().identity());
  EXPECT_EQ(InputSpace().description(), "Linear Rec.709");
}

TEST(InputSpace, WithoutNameOrAttributeTheSceneLinearRoleOfTheBuiltinConfig) {
  const auto s = InputSpace::resolve(display::load_config(""), "", std::nullopt);
  EXPECT_TRUE(s.identity());
  EXPECT_EQ(s.description(), "scene_linear role ('Linear Rec.709')");
}

TEST(InputSpace, TheAttributeGivesTheChromaticitiesMatrix) {
  const auto s = InputSpace::resolve(display::load_config(""), "", aces_ap1());
  EXPECT_FALSE(s.identity());
  ASSERT_TRUE(s.matrix());
  EXPECT_EQ(max_abs_difference(*s.matrix(), to_rec709(aces_ap1())), 0.0);
  EXPECT_EQ(s.description(), "chromaticities attribute (ACEScg (AP1) primaries, ACES white (D60))");
  // An attribute of Rec.709 primaries converts nothing.
  EXPECT_TRUE(InputSpace::resolve(display::load_config(""), "", rec709()).identity());
}

TEST(InputSpace, NamedSpaceOfTheShippedConfigMatchesTheChromaticities) {
  if (!std::filesystem::exists(kShipped)) GTEST_SKIP() << "no " << kShipped;
  const auto config = display::load_config(kShipped);
  for (const auto& [name, c] : {std::pair{"ACEScg", aces_ap1()}, std::pair{"ACES2065-1", aces_ap0()},
                                std::pair{"Linear Rec.2020", rec2020()}, std::pair{"CIE-XYZ-D65", cie_xyz()}}) {
    const auto m = named_space_matrix(config, name);
    ASSERT_TRUE(m) << name;
    EXPECT_LT(max_abs_difference(*m, to_rec709(c)), 2e-4) << name;
  }
  EXPECT_TRUE(InputSpace::resolve(config, "Linear Rec.709", std::nullopt).identity());
}

TEST(InputSpace, NamedSpaceOfBlendersConfig) {
  if (!std::filesystem::exists(kBlender)) GTEST_SKIP() << "no " << kBlender;
  const auto config = display::load_config(kBlender);
  const auto ap1 = named_space_matrix(config, "Linear ACEScg");
  ASSERT_TRUE(ap1);
  EXPECT_LT(max_abs_difference(*ap1, to_rec709(aces_ap1())), 1e-3);
  const auto ap0 = named_space_matrix(config, "Linear ACES");
  ASSERT_TRUE(ap0);
  EXPECT_LT(max_abs_difference(*ap0, to_rec709(aces_ap0())), 1e-3);
  // A log encoding is no matrix: OCIO converts it pixel by pixel.
  EXPECT_FALSE(named_space_matrix(config, "Filmic Log"));
  const auto log = InputSpace::resolve(config, "Filmic Log", std::nullopt);
  EXPECT_FALSE(log.identity());
  float px[4] = {0.5f, 0.5f, 0.5f, 0.25f};
  log.apply(px, 1, 4);
  EXPECT_GT(std::abs(px[0] - 0.5f), 1e-3f);
  EXPECT_EQ(px[3], 0.25f);
}

TEST(InputSpace, NameAndAttributeThatDisagreeWarnNamingBoth) {
  if (!std::filesystem::exists(kShipped)) GTEST_SKIP() << "no " << kShipped;
  const auto config = display::load_config(kShipped);
  std::string w;
  const auto s = InputSpace::resolve(config, "ACEScg", rec709(), &w);
  EXPECT_EQ(s.description(), "OCIO colour space 'ACEScg'");
  EXPECT_NE(w.find("'ACEScg'"), std::string::npos) << w;
  EXPECT_NE(w.find("Rec.709/sRGB primaries"), std::string::npos) << w;
  EXPECT_EQ(w.find('\n'), std::string::npos);
  InputSpace::resolve(config, "ACEScg", aces_ap1(), &w);
  EXPECT_EQ(w, "");
}

TEST(InputSpace, UnknownNameIsAUsageErrorListingSomeSpaces) {
  const auto config = display::load_config("");
  try {
    check_colorspace_name(config, "No Such Space", "built-in");
    FAIL() << "accepted an unknown name";
  } catch (const UsageError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'No Such Space'"), std::string::npos) << m;
    EXPECT_NE(m.find("'Linear Rec.709'"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(check_colorspace_name(config, "scene_linear", "built-in"));  // roles count
}

TEST(InputSpace, ApplyConvertsRgbOnlyAndLeavesNonFinitePixels) {
  const auto s = InputSpace::resolve(display::load_config(""), "", aces_ap1());
  const float inf = std::numeric_limits<float>::infinity();
  float px[8] = {1.f, 0.f, 0.f, 0.5f, inf, 1.f, 2.f, 1.f};
  s.apply(px, 2, 4);
  const Mat3 m = to_rec709(aces_ap1());
  EXPECT_NEAR(px[0], m.m[0][0], 1e-6);
  EXPECT_NEAR(px[1], m.m[1][0], 1e-6);
  EXPECT_NEAR(px[2], m.m[2][0], 1e-6);
  EXPECT_EQ(px[3], 0.5f);
  EXPECT_EQ(px[4], inf);
  EXPECT_EQ(px[5], 1.f);
  EXPECT_EQ(px[6], 2.f);
}

TEST(InputSpace, RoundingResidueIsZeroButSmallColourIsKept) {
  // Pure Rec.709 blue, stored as ACEScg float32 by the derivation from the primaries: back in
  // Rec.709 its red and green are float32 residue, which must come back as exactly 0.
  const Mat3 to_ap1 = to_rec709(aces_ap1()).inverse();
  float px[9];
  const double b = 1767.3861;
  const double pixels[3][3] = {{0, 0, b}, {b * 1e-3, 0, b}, {b * 1e-5, 0, b}};
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 3; ++k) px[3 * p + k] = float(to_ap1.m[k][0] * pixels[p][0] + to_ap1.m[k][2] * pixels[p][2]);
  InputSpace::resolve(display::load_config(""), "", aces_ap1()).apply(px, 3, 3);
  EXPECT_EQ(px[0], 0.f);
  EXPECT_EQ(px[1], 0.f);
  EXPECT_NEAR(px[2], b, 0.01);
  // A red a thousandth, and a hundred-thousandth (17 stops below), of the blue is colour: a
  // per-channel curve shows it (0.0177 is 15 of 255 through Reinhard and sRGB).
  EXPECT_NEAR(px[3], b * 1e-3, 1e-4);
  EXPECT_EQ(px[4], 0.f);
  EXPECT_NEAR(px[6], b * 1e-5, 1e-4);
  EXPECT_GT(px[6], 0.f);
  // A red 20 stops below a green (the terms that make it cancel to 8e-7 of their sum) is still
  // above what float32 storage leaves (6e-8 of the sum): kept. Reinhard shows it as 21 of 255.
  const double g = 7381.4663, r = 0.00657;
  float green[3];
  for (int k = 0; k < 3; ++k) green[k] = float(to_ap1.m[k][0] * r + to_ap1.m[k][1] * g);
  InputSpace::resolve(display::load_config(""), "", aces_ap1()).apply(green, 1, 3);
  EXPECT_NEAR(green[0], r, 1e-3);
  EXPECT_GT(green[0], 0.003f);
  EXPECT_NEAR(green[1], g, 0.01);
}

}  // namespace
}  // namespace cgtmo::color
