// resolve_params: unknown keys, numbers that do not parse, ranges, choices, image defaults.
#include <gtest/gtest.h>

#include "cgtmo/errors.h"
#include "cgtmo/operators/registry.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

ParamValues resolve(const std::string& op, const Params& given, const ImageStats* stats = nullptr) {
  return resolve_params(find_operator(op), given, stats);
}

TEST(ResolveParams, UnknownKeyIsAUsageErrorNamingIt) {
  try {
    resolve("reinhard-ext", {{"whte", "2"}});
    FAIL() << "accepted an unknown key";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("whte"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("white"), std::string::npos) << e.what();  // lists the known ones
  }
  EXPECT_THROW(resolve("linear", {{"white", "1"}}), UsageError);  // linear has none
}

TEST(ResolveParams, BadNumbers) {
  for (const char* bad : {"", "abc", "1.5x", "x1", "nan", "inf", "-inf", "1e999", "2,5"})
    EXPECT_THROW(resolve("aces-narkowicz", {{"scale", bad}}), UsageError) << "'" << bad << "'";
  EXPECT_DOUBLE_EQ(resolve("aces-narkowicz", {{"scale", "0.6"}}).number("scale"), 0.6);
  EXPECT_DOUBLE_EQ(resolve("aces-narkowicz", {{"scale", "6e-1"}}).number("scale"), 0.6);
}

// An empty value is refused for every type, also where "" is the default (camera's curve): it
// must not quietly stand for the default.
TEST(ResolveParams, EmptyValueIsRefusedNamingTheParameter) {
  for (const auto& [op, key] : std::vector<std::pair<std::string, std::string>>{
           {"camera", "table"}, {"reinhard", "mode"}, {"aces-narkowicz", "scale"}}) {
    try {
      resolve(op, {{key, ""}});
      FAIL() << op << " accepted " << key << "=";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("parameter '" + key + "' is given an empty value"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(resolve("camera", {}).text("curve"), "");  // left out: the default
  // A text whose default is "" takes "" as that very value, so resolved parameters resolve again.
  EXPECT_EQ(resolve("camera", {{"curve", ""}}).text("curve"), "");
}

TEST(ResolveParams, RangesAreInclusive) {
  EXPECT_THROW(resolve("drago", {{"b", "0.49"}, {"lw_max", "1"}, {"lw_a", "1"}}), UsageError);
  EXPECT_THROW(resolve("drago", {{"b", "1.01"}, {"lw_max", "1"}, {"lw_a", "1"}}), UsageError);
  EXPECT_DOUBLE_EQ(resolve("drago", {{"b", "0.5"}, {"lw_max", "1"}, {"lw_a", "1"}}).number("b"), 0.5);
  EXPECT_DOUBLE_EQ(resolve("drago", {{"b", "1"}, {"lw_max", "1"}, {"lw_a", "1"}}).number("b"), 1.0);
  EXPECT_THROW(resolve("reinhard-ext", {{"white", "0"}}), UsageError);
  EXPECT_THROW(resolve("reinhard-ext", {{"white", "-3"}}), UsageError);
  EXPECT_THROW(resolve("hable", {{"white", "1e6"}}), UsageError);
}

TEST(ResolveParams, Choices) {
  EXPECT_EQ(resolve("reinhard", {}).text("mode"), "per-channel");
  EXPECT_EQ(resolve("reinhard", {{"mode", "luminance"}}).text("mode"), "luminance");
  EXPECT_EQ(resolve("reinhard", {{"mode", "max-rgb"}}).text("mode"), "max-rgb");
  EXPECT_THROW(resolve("reinhard", {{"mode", "Luminance"}}), UsageError);
  EXPECT_THROW(resolve("reinhard", {{"mode", ""}}), UsageError);
  EXPECT_EQ(resolve("drago", {{"lw_max", "1"}, {"lw_a", "1"}}).text("mode"), "luminance");
}

TEST(ResolveParams, DefaultsAreFilledIn) {
  const ParamValues v = resolve("hable", {});
  EXPECT_DOUBLE_EQ(v.number("A"), 0.15);
  EXPECT_DOUBLE_EQ(v.number("F"), 0.30);
  EXPECT_DOUBLE_EQ(v.number("exposure_bias"), 2.0);
  EXPECT_DOUBLE_EQ(v.number("white"), 11.2);
  EXPECT_DOUBLE_EQ(v.number("saturation"), 1.0);
  EXPECT_EQ(resolve("camera", {}).text("table"), "builtin");
  EXPECT_EQ(resolve("camera", {{"table", "/some/file.dorf"}}).text("table"), "/some/file.dorf");
}

TEST(ResolveParams, ImageDefaults) {
  ImageStats s;
  s.max_channel = 3.0;
  s.max_luminance = 2.0;
  s.log_average_luminance = 0.1;
  EXPECT_DOUBLE_EQ(resolve("reinhard-ext", {}, &s).number("white"), 3.0);
  EXPECT_DOUBLE_EQ(resolve("reinhard-lum", {}, &s).number("white"), 2.0);
  const ParamValues d = resolve("drago", {}, &s);
  EXPECT_DOUBLE_EQ(d.number("lw_max"), 2.0);
  EXPECT_DOUBLE_EQ(d.number("lw_a"), 0.1);
  // A given value wins over the statistic, and then no statistics are needed.
  EXPECT_DOUBLE_EQ(resolve("reinhard-ext", {{"white", "5"}}, &s).number("white"), 5.0);
  EXPECT_FALSE(needs_image_stats(find_operator("reinhard-ext"), {{"white", "5"}}));
  EXPECT_TRUE(needs_image_stats(find_operator("reinhard-ext"), {}));
  EXPECT_TRUE(needs_image_stats(find_operator("drago"), {{"lw_max", "5"}}));  // lw_a still from the image
  EXPECT_FALSE(needs_image_stats(find_operator("hable"), {}));
  EXPECT_THROW(resolve("reinhard-ext", {}, nullptr), UsageError);
}

TEST(ResolveParams, ImageDefaultsAreClampedIntoRange) {
  ImageStats black;  // all zero: an all-black image
  EXPECT_DOUBLE_EQ(resolve("reinhard-ext", {}, &black).number("white"), 1e-6);
  EXPECT_DOUBLE_EQ(resolve("drago", {}, &black).number("lw_max"), 1e-6);
  ImageStats huge;
  huge.max_channel = 1e9;
  EXPECT_DOUBLE_EQ(resolve("reinhard-ext", {}, &huge).number("white"), 65504.0);
}

}  // namespace
}  // namespace cgtmo::operators::test
