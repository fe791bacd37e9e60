// pipeline/request.cpp: the checks every apply request passes, whichever pipeline runs it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/pipeline/request.h"

namespace cgtmo::pipeline {
namespace {

std::string exposure_message(double ev) {
  try {
    check_exposure(ev);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckExposure, WithinSixtyFourStopsEitherWay) {
  for (double ev : {0.0, 1.5, -10.0, 64.0, -64.0}) EXPECT_EQ(exposure_message(ev), "") << ev;
  const std::string refused = "exposure must be within [-64, 64] stops";
  for (double ev : {64.001, -64.5, 1e300, std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
    EXPECT_EQ(exposure_message(ev), refused) << ev;
}

TEST(SetupColour, EncodingResolvesTheDefaultDisplayAndView) {
  unsetenv("OCIO");  // the built-in config
  const ColourSetup s = setup_colour(true, "", "", "", "");
  ASSERT_TRUE(s.config);
  ASSERT_TRUE(s.encoder);
  EXPECT_EQ(s.encoder->display(), "sRGB");
  EXPECT_EQ(s.encoder->view(), "Standard");
  EXPECT_EQ(s.config_origin, "built-in config");
  const ColourSetup p3 = setup_colour(true, "", "", "Display P3", "");
  EXPECT_EQ(p3.encoder->display(), "Display P3");
}

TEST(SetupColour, LinearOutputHasNoEncoder) {
  unsetenv("OCIO");
  const ColourSetup s = setup_colour(false, "", "", "", "");
  EXPECT_FALSE(s.encoder);
  EXPECT_EQ(s.config_origin, "");
  // A named input colour space still needs the config.
  const ColourSetup named = setup_colour(false, "", "Linear Rec.709", "", "");
  EXPECT_TRUE(named.config);
  EXPECT_FALSE(named.encoder);
}

TEST(SetupColour, RefusesWhatItCannotHonour) {
  unsetenv("OCIO");
  try {
    setup_colour(false, "", "", "sRGB", "");
    FAIL() << "a display without encoding was accepted";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "a display or view cannot be combined with linear (unencoded) output");
  }
  EXPECT_THROW(setup_colour(true, "", "", "No Such Display", ""), UsageError);
  EXPECT_THROW(setup_colour(true, "", "", "sRGB", "No Such View"), UsageError);
  EXPECT_THROW(setup_colour(true, "", "No Such Space", "", ""), UsageError);
  EXPECT_THROW(setup_colour(false, "", "No Such Space", "", ""), UsageError);
}

}  // namespace
}  // namespace cgtmo::pipeline
