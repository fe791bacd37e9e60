// display/encode.cpp: the display choice check, and one-call encoding against the published sRGB
// and Rec.1886 curves (not against DisplayEncoder's own output).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cgtmo/display/encode.h"
#include "cgtmo/errors.h"

namespace cgtmo::display {
namespace {

const char* kNoDisplayMessage = "a display or view cannot be combined with linear (unencoded) output";

std::string message_of(bool encode, const std::string& display, const std::string& view) {
  try {
    check_display_choice(encode, display, view);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckDisplayChoice, DisplayOrViewOnlyWithEncoding) {
  EXPECT_EQ(message_of(true, "", ""), "");
  EXPECT_EQ(message_of(true, "sRGB", "Standard"), "");
  EXPECT_EQ(message_of(false, "", ""), "");
  EXPECT_EQ(message_of(false, "sRGB", ""), kNoDisplayMessage);
  EXPECT_EQ(message_of(false, "", "Standard"), kNoDisplayMessage);
  EXPECT_EQ(message_of(false, "sRGB", "Raw"), kNoDisplayMessage);
}

double srgb_oetf(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055; }

TEST(EncodeForDisplay, BuiltinDefaultIsSrgbStandard) {
  unsetenv("OCIO");  // the built-in config, whatever the environment names
  const std::vector<float> in = {0.0f, 0.002f, 0.18f, 0.5f, 1.0f, 0.8f, 0.1f, 0.02f};
  std::vector<float> px(in.size() / 2 * 3);
  for (std::size_t i = 0; i < in.size() / 2; ++i) px[3 * i] = px[3 * i + 1] = px[3 * i + 2] = in[i];
  std::string display, view, origin;
  encode_for_display(px.data(), int(in.size() / 2), 1, 3, "", "", "", &display, &view, &origin);
  EXPECT_EQ(display, "sRGB");
  EXPECT_EQ(view, "Standard");
  EXPECT_EQ(origin, "built-in config");
  for (std::size_t i = 0; i < in.size() / 2; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[3 * i + c], srgb_oetf(in[i]), 1e-4) << in[i];
}

TEST(EncodeForDisplay, NamedDisplayAndAlphaUntouched) {
  unsetenv("OCIO");
  // Rec.1886 with a black of 0 is a pure 2.4 power; alpha passes through.
  std::vector<float> px = {0.18f, 0.5f, 1.0f, 0.25f};
  encode_for_display(px.data(), 1, 1, 4, "", "Rec.1886", "");
  EXPECT_NEAR(px[0], std::pow(0.18, 1 / 2.4), 1e-4);
  EXPECT_NEAR(px[1], std::pow(0.5, 1 / 2.4), 1e-4);
  EXPECT_NEAR(px[2], 1.0, 1e-4);
  EXPECT_EQ(px[3], 0.25f);
}

TEST(EncodeForDisplay, UnknownDisplayIsAUsageError) {
  unsetenv("OCIO");
  std::vector<float> px = {0.18f, 0.18f, 0.18f};
  EXPECT_THROW(encode_for_display(px.data(), 1, 1, 3, "", "No Such Display", ""), UsageError);
}

}  // namespace
}  // namespace cgtmo::display
