// src/cgtmo/scene/sidecar.cpp: parsing the render sidecar, and its errors.
#include "cgtmo/scene/sidecar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/errors.h"

using namespace cgtmo;
using namespace cgtmo::scene;

static const char* kMinimal = R"({
  "camera": {"world_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,2],[0,0,0,1]], "fov_x_rad": 1.0, "resolution": [64, 36]},
  "lights": [{"name": "key", "type": "AREA", "lightgroup": "key", "luminance": 25.0, "power": 100, "size": [1, 1],
              "in_frame": true},
             {"name": "world", "type": "WORLD", "lightgroup": "world", "luminance": 0}],
  "probe": {"file": "x.probe.exr", "projection": "equirectangular", "resolution": [64, 32]}
})";

static std::string message_of(const std::string& text) {
  try {
    parse_sidecar(text, "s.json");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(Sidecar, ParsesTheRequiredAndOptionalFields) {
  const Sidecar s = parse_sidecar(kMinimal, "s.json");
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 36);
  EXPECT_DOUBLE_EQ(s.camera.world_matrix[11], 2.0);
  // Footprint derived when absent: 2 tan(0.5) / 64.
  EXPECT_NEAR(s.camera.pixel_footprint_at_1m, 2.0 * 0.54630248984379 / 64.0, 1e-12);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, "AREA");
  EXPECT_DOUBLE_EQ(s.lights[0].power, 100.0);
  EXPECT_TRUE(std::isnan(s.lights[0].radius));
  ASSERT_TRUE(s.lights[0].in_frame.has_value());
  EXPECT_TRUE(*s.lights[0].in_frame);
  EXPECT_FALSE(s.lights[1].in_frame.has_value());
  EXPECT_EQ(s.light_for_group("world"), &s.lights[1]);
  EXPECT_EQ(s.light_for_group("nope"), nullptr);
  ASSERT_TRUE(s.probe.has_value());
  EXPECT_EQ(s.probe->width, 64);
  EXPECT_EQ(s.probe->projection, "equirectangular");
}

TEST(Sidecar, NotJson) {
  EXPECT_NE(message_of("camera = 1").find("not JSON"), std::string::npos);
  EXPECT_NE(message_of("").find("not JSON"), std::string::npos);
  EXPECT_NE(message_of("[1, 2]").find("not a JSON object"), std::string::npos);
}

TEST(Sidecar, MissingFieldsAreNamed) {
  EXPECT_NE(message_of(R"({"lights": []})").find("lacks 'camera'"), std::string::npos);
  EXPECT_NE(message_of(R"({"camera": {"fov_x_rad": 1, "resolution": [2, 1]}, "lights": []})").find("lacks 'world_matrix'"),
            std::string::npos);
  std::string t = kMinimal;
  t.replace(t.find("\"luminance\": 25.0, "), 19, "");
  EXPECT_NE(message_of(t).find("lights[0] lacks 'luminance'"), std::string::npos) << message_of(t);
}

TEST(Sidecar, WrongTypesAreNamed) {
  std::string t = kMinimal;
  t.replace(t.find("[64, 36]"), 8, "[64]");
  EXPECT_NE(message_of(t).find("camera.resolution"), std::string::npos);
  t = kMinimal;
  t.replace(t.find("\"luminance\": 25.0"), 17, "\"luminance\": \"bright\"");
  EXPECT_NE(message_of(t).find("lights[0].luminance is not a number"), std::string::npos) << message_of(t);
  t = kMinimal;
  t.replace(t.find("\"luminance\": 25.0"), 17, "\"luminance\": -1");
  EXPECT_NE(message_of(t).find("negative"), std::string::npos);
}

TEST(Sidecar, ReadsFilesAndNamesMissingOnes) {
  EXPECT_THROW(read_sidecar("/nonexistent/cgtmo/s.json"), DataError);
}

// Found by fuzz_sidecar: a number beyond double made nlohmann throw out_of_range, which escaped.
TEST(Sidecar, NumberOutOfRangeIsADataError) {
  const std::string huge(400, '3');
  EXPECT_THROW(cgtmo::scene::parse_sidecar(huge, "huge"), cgtmo::DataError);
  EXPECT_THROW(cgtmo::scene::parse_sidecar("{\"camera\": " + huge + "}", "huge"), cgtmo::DataError);
}

// Resolutions beyond int were converted before the range check (undefined behaviour: UBSan
// aborted on 1e10, 2^31 and 1e300). Each is now one DataError naming the field.
TEST(Sidecar, ResolutionBeyondIntIsADataError) {
  for (const char* bad : {"[1e10, 36]", "[64, 2147483648]", "[1e300, 1e300]", "[-1e300, 36]", "[64.5, 36]", "[0, 36]"}) {
    std::string t = kMinimal;
    t.replace(t.find("[64, 36]"), 8, bad);
    EXPECT_NE(message_of(t).find("camera.resolution is not [width, height]"), std::string::npos) << bad << ": " << message_of(t);
    t = kMinimal;
    t.replace(t.find("[64, 32]"), 8, bad);
    EXPECT_NE(message_of(t).find("probe.resolution is not [width, height]"), std::string::npos) << bad << ": " << message_of(t);
  }
  std::string t = kMinimal;
  t.replace(t.find("[64, 36]"), 8, "[1048576, 1]");
  EXPECT_EQ(message_of(t), "");
}

// JSON that is not an object is no tool's document: bad data, whatever the face (it was taken for
// another tool's file and ignored: info and apply exited 0 as if there were no sidecar). An object
// of another tool (neither camera nor lights) is still foreign.
TEST(Sidecar, JsonThatIsNotAnObjectIsBadDataNotForeign) {
  const std::pair<const char*, const char*> kinds[] = {
      {"[1, 2]", "an array"}, {"null", "null"}, {"42", "a number"}, {"-0.5e3", "a number"}, {"\"text\"", "a string"}, {"true", "a boolean"}};
  for (const auto& [text, kind] : kinds) {
    EXPECT_FALSE(is_foreign_json(text)) << text;
    EXPECT_EQ(message_of(text), std::string("sidecar 's.json': not a JSON object (") + kind + ")") << text;
  }
  EXPECT_TRUE(is_foreign_json(R"({"generator": "another tool", "frames": [1, 2]})"));
  EXPECT_FALSE(is_foreign_json("{\"camera\": 1, \"lights\": []}"));  // ours, broken
  EXPECT_FALSE(is_foreign_json(R"({"format": "cgtmo-scene-sidecar", "camera": 1})"));  // ours by its format, broken
}

// Another tool's file may describe a camera of its own: without our format and our two required
// keys it is foreign (a warning and the fallbacks), never an error that stops the frame.
TEST(Sidecar, AnotherSchemaWithACameraIsForeign) {
  EXPECT_TRUE(is_foreign_json(R"({"camera": {"fov": 50, "name": "shotcam"}, "frames": [1001, 1100]})"));
  EXPECT_TRUE(is_foreign_json(R"({"format": "usd-camera-export", "camera": {}, "lights": []})"));
  EXPECT_TRUE(is_foreign_json(R"({"format": 3, "camera": {}, "lights": []})"));
}
