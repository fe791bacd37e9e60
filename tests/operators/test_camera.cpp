// Camera response: DoRF table parsing (valid, malformed, user-supplied file), interpolation between
// samples (the seed guide's upper_bound lookup took the sample above as the lower one), iso.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "cgtmo/errors.h"
#include "cgtmo/operators/camera_table.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

// Two curves; the first is 0 -> 0, 0.5 -> 0.8, 1 -> 1, the second the identity on 3 samples.
const char* kTable =
    "# a comment\n"
    "test camera A\n"
    "graph\n"
    "I =\n"
    "0 0.5\n"
    "1\n"
    "B =\n"
    "0 0.8 1\n"
    "\n"
    "test camera B\n"
    "I=\n"
    "0.0 0.5 1.0\n"
    "B=\n"
    "0.0 0.5 1.0\n";

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(CameraTable, ParsesAValidTable) {
  const auto t = parse_dorf(kTable, "test");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].name, "test camera A");
  EXPECT_EQ(t[0].irradiance, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(t[0].intensity, (std::vector<double>{0, 0.8, 1}));
  EXPECT_EQ(t[1].name, "test camera B");
  EXPECT_EQ(t[1].intensity.size(), 3u);
}

TEST(CameraTable, InterpolatesBetweenTheSamplesAroundTheValue) {
  const auto t = parse_dorf(kTable, "test");
  // 0.25 lies between 0 (-> 0) and 0.5 (-> 0.8): 0.4. The guide's lookup would have used the
  // samples 0.5 and 1 and extrapolated to 0.7.
  EXPECT_NEAR(sample_response(t[0], 0.25), 0.4, 1e-12);
  EXPECT_NEAR(sample_response(t[0], 0.75), 0.9, 1e-12);
  EXPECT_NEAR(sample_response(t[0], 0.5), 0.8, 1e-12);  // on a sample
  EXPECT_NEAR(sample_response(t[0], 0.1), 0.16, 1e-12);
  EXPECT_EQ(sample_response(t[0], 0.0), 0.0);
  EXPECT_EQ(sample_response(t[0], -1.0), 0.0);  // below: the first intensity
  EXPECT_EQ(sample_response(t[0], 1.0), 1.0);
  EXPECT_EQ(sample_response(t[0], 7.0), 1.0);  // above: the last intensity
}

void expect_malformed(const std::string& text, const std::string& what) {
  try {
    parse_dorf(text, "bad.dorf");
    ADD_FAILURE() << "accepted: " << what;
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.dorf"), std::string::npos) << e.what();
  }
}

TEST(CameraTable, RejectsMalformedTables) {
  expect_malformed("", "empty text");
  expect_malformed("# only a comment\n", "no curve");
  expect_malformed("I =\n0 1\nB =\n0 1\n", "I = without a name");
  expect_malformed("cam\nB =\n0 1\n", "B = before I =");
  expect_malformed("cam\n0 1\nI =\n0 1\nB =\n0 1\n", "numbers before I =");
  expect_malformed("cam\nI =\n0 0.5 1\nB =\n0 1\n", "length mismatch");
  expect_malformed("cam\nI =\n0.5\nB =\n0.5\n", "one sample");
  expect_malformed("cam\nI =\n0 0.7 0.5 1\nB =\n0 0.2 0.3 1\n", "irradiance decreasing");
  expect_malformed("cam\nI =\n0 1.5\nB =\n0 1\n", "irradiance above 1");
  expect_malformed("cam\nI =\n0 1\nB =\n-0.1 1\n", "negative intensity");
  expect_malformed("cam\nI =\n0 0.5x 1\nB =\n0 0.5 1\n", "not a number");
  expect_malformed("cam\nI =\n0 nan 1\nB =\n0 0.5 1\n", "nan");
  expect_malformed("cam\nI =\n0 1\nB =\n0 1\nnext\nI =\n0 1\n", "second curve without B");
}

TEST(CameraTable, BuiltinTableIsValidAndMonotonic) {
  const auto& t = builtin_camera_responses();
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].name, "cgtmo film neutral");
  for (const auto& c : t) {
    EXPECT_EQ(c.irradiance.front(), 0.0) << c.name;
    EXPECT_EQ(c.irradiance.back(), 1.0) << c.name;
    EXPECT_NEAR(c.intensity.front(), 0.0, 1e-6) << c.name;
    EXPECT_NEAR(c.intensity.back(), 1.0, 1e-6) << c.name;
    for (std::size_t i = 1; i < c.intensity.size(); ++i) EXPECT_GE(c.intensity[i], c.intensity[i - 1]) << c.name << i;
  }
}

TEST(CameraTable, BuiltinTableIsTheDocumentedFormula) {
  // data/camera/cgtmo-film.dorf comes from scripts/make_camera_table.py:
  // B(E) = ((1 + k) E / (E + k))^(1 / g) at E = i / 255; a stale or hand-edited table fails here.
  const struct { const char* name; double k, g; } curves[] = {
      {"cgtmo film neutral", 0.25, 1.6}, {"cgtmo film soft", 0.6, 1.9}, {"cgtmo film contrast", 0.12, 1.3}};
  const auto& t = builtin_camera_responses();
  ASSERT_EQ(t.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(t[c].name, curves[c].name);
    ASSERT_EQ(t[c].irradiance.size(), 256u);
    for (int i = 0; i < 256; i += 15) {
      const double e = i / 255.0;
      EXPECT_NEAR(t[c].irradiance[i], e, 1e-7);
      EXPECT_NEAR(t[c].intensity[i], std::pow((1 + curves[c].k) * e / (e + curves[c].k), 1 / curves[c].g), 1e-7)
          << curves[c].name << " " << i;
    }
  }
}

TEST(CameraOperator, UserTableAndCurveChoice) {
  const std::string path = write_temp("user.dorf", kTable);
  EXPECT_NEAR(grey("camera", 0.25, {{"table", path}}), 0.4, 1e-6);  // first curve by default
  EXPECT_NEAR(grey("camera", 0.25, {{"table", path}, {"curve", "test camera B"}}), 0.25, 1e-6);
  EXPECT_THROW(grey("camera", 0.25, {{"table", path}, {"curve", "nope"}}), UsageError);
  EXPECT_THROW(grey("camera", 0.25, {{"table", ::testing::TempDir() + "/missing.dorf"}}), DataError);
  const std::string bad = write_temp("bad.dorf", "cam\nI =\n0 1\n");
  EXPECT_THROW(grey("camera", 0.25, {{"table", bad}}), DataError);
}

TEST(CameraOperator, IsoStretchesTheIrradianceAxis) {
  const std::string path = write_temp("iso.dorf", kTable);
  // iso 2: input 0.5 reaches irradiance 0.25 -> 0.4; input 2 reaches the top of the curve.
  EXPECT_NEAR(grey("camera", 0.5, {{"table", path}, {"iso", "2"}}), 0.4, 1e-6);
  EXPECT_NEAR(grey("camera", 1.5, {{"table", path}, {"iso", "2"}}), 0.9, 1e-6);
  EXPECT_EQ(grey("camera", 2.0, {{"table", path}, {"iso", "2"}}), 1.0);
  EXPECT_EQ(grey("camera", 100.0, {{"table", path}, {"iso", "2"}}), 1.0);
  EXPECT_NEAR(grey("camera", 0.025, {{"table", path}, {"iso", "0.1"}}), 0.4, 1e-6);
}

TEST(CameraOperator, BuiltinByDefaultPerChannel) {
  const auto& neutral = builtin_camera_responses()[0];
  const RGB out = run1("camera", {0.3f, 0.6f, 0.05f});
  EXPECT_NEAR(out[0], sample_response(neutral, 0.3), 1e-6);
  EXPECT_NEAR(out[1], sample_response(neutral, 0.6), 1e-6);
  EXPECT_NEAR(out[2], sample_response(neutral, 0.05), 1e-6);
}

}  // namespace
}  // namespace cgtmo::operators::test
