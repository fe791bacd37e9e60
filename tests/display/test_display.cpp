// src/cgtmo/display/display.cpp: the built-in config and DisplayEncoder's encoding, checked
// against the published transfer functions rather than against OpenColorIO's own output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"

namespace cgtmo::display {
namespace {

// IEC 61966-2-1.
double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

TEST(DisplayEncoder, DefaultIsSrgbStandardAndEncodesWithTheSrgbCurve) {
  ::unsetenv("OCIO");  // nothing given and no $OCIO: the built-in config
  std::string origin;
  const DisplayEncoder enc(load_config("", &origin), "", "");
  EXPECT_FALSE(origin.empty());
  EXPECT_EQ(enc.display(), "sRGB");
  EXPECT_EQ(enc.view(), "Standard");
  const std::vector<float> in = {0.f, 0.001f, 0.0031308f, 0.05f, 0.18f, 0.5f, 0.9f, 1.f, 0.2f};
  std::vector<float> px = in;
  enc.apply(px.data(), 3, 1, 3);
  for (std::size_t i = 0; i < in.size(); ++i) EXPECT_NEAR(px[i], srgb_encode(in[i]), 2e-4) << in[i];
  // Alpha passes through.
  std::vector<float> rgba = {0.18f, 0.18f, 0.18f, 0.25f};
  enc.apply(rgba.data(), 1, 1, 4);
  EXPECT_NEAR(rgba[0], srgb_encode(0.18), 2e-4);
  EXPECT_EQ(rgba[3], 0.25f);
}

TEST(DisplayEncoder, RawViewLeavesValuesAlone) {
  ::unsetenv("OCIO");
  const DisplayEncoder enc(load_config(""), "sRGB", "Raw");
  std::vector<float> px = {0.f, 0.18f, 0.75f};
  enc.apply(px.data(), 1, 1, 3);
  EXPECT_NEAR(px[0], 0.f, 1e-6);
  EXPECT_NEAR(px[1], 0.18f, 1e-6);
  EXPECT_NEAR(px[2], 0.75f, 1e-6);
}

TEST(DisplayEncoder, UnknownDisplayOrViewNamesTheChoices) {
  ::unsetenv("OCIO");
  const auto config = load_config("");
  try {
    DisplayEncoder(config, "sRBG", "");
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("sRBG"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sRGB"), std::string::npos) << e.what();
  }
  try {
    DisplayEncoder(config, "sRGB", "Standrd");
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("Standard"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cgtmo::display
