// describe_display against the published colorimetry of each display (not against its own fit),
// and the views that apply an operator.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cgtmo/display/display.h"
#include "cgtmo/display/profile.h"

namespace cgtmo::display {
namespace {

OCIO::ConstConfigRcPtr from_yaml(const std::string& yaml) {
  std::istringstream s(yaml);
  return OCIO::Config::CreateFromStream(s);
}

void expect_xy(const std::array<double, 2>& got, double x, double y) {
  EXPECT_NEAR(got[0], x, 2e-3);
  EXPECT_NEAR(got[1], y, 2e-3);
}

TEST(DescribeDisplay, BuiltinDisplaysHaveTheirPublishedPrimariesAndCurves) {
  const auto config = load_config("");
  const DisplayProfile srgb = describe_display(config, "sRGB", "Standard");
  ASSERT_TRUE(srgb.known) << srgb.why;
  expect_xy(srgb.primaries[0], 0.64, 0.33);
  expect_xy(srgb.primaries[1], 0.30, 0.60);
  expect_xy(srgb.primaries[2], 0.15, 0.06);
  expect_xy(srgb.white, 0.3127, 0.3290);
  EXPECT_TRUE(srgb.srgb_curve);
  EXPECT_FALSE(srgb.icc.empty());

  const DisplayProfile p3 = describe_display(config, "Display P3", "Standard");
  ASSERT_TRUE(p3.known) << p3.why;
  expect_xy(p3.primaries[0], 0.680, 0.320);
  expect_xy(p3.primaries[1], 0.265, 0.690);
  expect_xy(p3.primaries[2], 0.150, 0.060);
  expect_xy(p3.white, 0.3127, 0.3290);
  EXPECT_TRUE(p3.srgb_curve);

  const DisplayProfile bt1886 = describe_display(config, "Rec.1886", "Standard");
  ASSERT_TRUE(bt1886.known) << bt1886.why;
  EXPECT_FALSE(bt1886.srgb_curve);
  EXPECT_DOUBLE_EQ(bt1886.gamma, 2.4);
  EXPECT_EQ(bt1886.transfer_name(), "gamma 2.40");
}

TEST(DescribeDisplay, RawAndCurvesThatDifferPerChannelAreUnknown) {
  const auto config = load_config("");
  const DisplayProfile raw = describe_display(config, "sRGB", "Raw");
  EXPECT_FALSE(raw.known);
  EXPECT_NE(raw.why.find("data"), std::string::npos) << raw.why;
  EXPECT_TRUE(raw.icc.empty());

  const auto odd = from_yaml(R"(ocio_profile_version: 2
roles: {default: lin, scene_linear: lin}
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  Odd:
    - !<View> {name: Standard, colorspace: odd}
  Toe:
    - !<View> {name: Standard, colorspace: toe}
colorspaces:
  - !<ColorSpace> {name: lin, isdata: false}
  - !<ColorSpace> {name: odd, isdata: false, from_scene_reference: !<ExponentTransform> {value: [2.4, 2.2, 2.6, 1], direction: inverse}}
  - !<ColorSpace> {name: toe, isdata: false, from_scene_reference: !<LogAffineTransform> {base: 2, logSideSlope: 0.05, logSideOffset: 0.6}}
)");
  EXPECT_FALSE(describe_display(odd, "Odd", "Standard").known);
  EXPECT_FALSE(describe_display(odd, "Toe", "Standard").known);
}

TEST(DescribeDisplay, LinearProfileIsRec709WithUnitGamma) {
  const DisplayProfile p = linear_rec709_profile();
  expect_xy(p.primaries[0], 0.64, 0.33);
  expect_xy(p.white, 0.3127, 0.3290);
  EXPECT_EQ(p.transfer_name(), "linear");
  EXPECT_FALSE(p.icc.empty());
}

TEST(ViewOperator, ShippedConfigViewsNameTheirOperator) {
  const auto config = load_config(std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio");
  EXPECT_EQ(DisplayEncoder(config, "sRGB", "agx").view_operator(), "agx");
  EXPECT_EQ(DisplayEncoder(config, "Display P3", "hable").view_operator(), "hable");
  EXPECT_EQ(DisplayEncoder(config, "sRGB", "Standard").view_operator(), "");
  // The operator view's encoding is its display's: the same profile as Standard.
  const DisplayProfile a = DisplayEncoder(config, "Display P3", "agx").profile();
  const DisplayProfile s = DisplayEncoder(config, "Display P3", "Standard").profile();
  ASSERT_TRUE(a.known) << a.why;
  EXPECT_EQ(a.colorspace, s.colorspace);
  expect_xy(a.primaries[0], 0.680, 0.320);
  EXPECT_TRUE(a.srgb_curve);
}

}  // namespace
}  // namespace cgtmo::display
