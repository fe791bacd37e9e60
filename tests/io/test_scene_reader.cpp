// src/cgtmo/io/scene_reader.cpp on the committed Blender renders (tests/scenes/<name>/).
// Expected values come from the scene scripts' parameters worked by hand, or from a second
// property of the data (Blender's background has Position and Normal exactly zero; light groups
// sum to Combined), never from the reader itself.
#include "cgtmo/io/scene_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cgtmo/errors.h"

using namespace cgtmo;
using scene::Pass;

static const std::string kScenes = std::string(CGTMO_SOURCE_DIR) + "/tests/scenes/";
static const char* kNames[] = {"cornell", "two-rooms", "sun-window", "night", "relief", "colored-lights", "lit-box", "dark-doorway"};

static std::string exr(const std::string& name) { return kScenes + name + "/" + name + ".exr"; }

static double lum(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

static io::SceneRequest everything() {
  io::SceneRequest r;
  r.required = scene::PassSet::all();
  r.probe = io::Companion::Require;
  r.sidecar = io::Companion::Require;
  r.needed_by = "the test";
  return r;
}

TEST(CommittedScenes, EveryPassProbeAndSidecarOfEveryScene) {
  for (const char* name : kNames) {
    SCOPED_TRACE(name);
    const io::Scene s = io::read_scene(exr(name), everything());
    const scene::Frame& f = s.frame;
    EXPECT_EQ(f.width, 480);
    EXPECT_EQ(f.height, 270);
    EXPECT_EQ(f.channels, 4);
    EXPECT_EQ(s.channels.scheme, "blender");
    ASSERT_TRUE(s.probe.has_value());
    EXPECT_EQ(s.probe->width, 64);
    EXPECT_EQ(s.probe->height, 32);
    ASSERT_TRUE(s.sidecar.has_value());
    EXPECT_EQ(s.sidecar->scene, name);
    // One light group per sidecar emitter (the world included), and nothing else.
    EXPECT_EQ(f.light_groups.size(), s.sidecar->lights.size());
    for (const auto& l : s.sidecar->lights) {
      EXPECT_TRUE(std::any_of(f.light_groups.begin(), f.light_groups.end(),
                              [&](const scene::LightGroupPlane& g) { return g.name == l.lightgroup; }))
          << l.lightgroup;
    }
    // Every emitter is in a group, so the groups sum to the beauty (half floats: 1e-3 of the frame).
    double groups = 0, beauty = 0;
    for (std::size_t i = 0; i < f.pixel_count(); ++i) {
      beauty += lum(&f.beauty[i * 4]);
      for (const auto& g : f.light_groups) groups += lum(&g.rgb[3 * i]);
    }
    EXPECT_NEAR(groups, beauty, 1e-3 * beauty);
  }
}

TEST(CommittedScenes, BackgroundIsWherePositionAndNormalAreZero) {
  // docs/platform.md: Blender writes Depth 1e10, Position (0,0,0) and Normal (0,0,0) on the background.
  // The reader masks from depth alone; the zero G-buffer is the independent witness.
  for (const char* name : {"cornell", "sun-window", "night"}) {
    SCOPED_TRACE(name);
    io::SceneRequest r;
    r.required = Pass::Depth | Pass::Position;
    r.probe = r.sidecar = io::Companion::Skip;
    const scene::Frame f = io::read_scene(exr(name), r).frame;
    std::size_t background = 0, mismatched = 0;
    for (std::size_t i = 0; i < f.pixel_count(); ++i) {
      const float* p = &f.position[3 * i];
      const bool zero = p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f;
      background += f.background[i];
      mismatched += (f.background[i] != 0) != zero;
    }
    EXPECT_EQ(mismatched, 0u);
    if (std::string(name) == "cornell") {
      // The box is open at the front and the world is black: about a third of the frame.
      EXPECT_GT(background, f.pixel_count() / 5);
      EXPECT_LT(background, f.pixel_count() / 2);
    }
  }
}

TEST(CommittedScenes, NormalsAreUnitOrMarkedInvalid) {
  io::SceneRequest r;
  r.required = Pass::Depth | Pass::Normal;
  r.probe = r.sidecar = io::Companion::Skip;
  const io::Scene s = io::read_scene(exr("cornell"), r);
  const scene::Frame& f = s.frame;
  std::size_t invalid_fg = 0, background = 0, background_with_normal = 0;
  for (std::size_t i = 0; i < f.pixel_count(); ++i) {
    const float* n = &f.normal[3 * i];
    const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
    if (f.normal_valid[i]) {
      ASSERT_NEAR(len, 1.0, 1e-6);
    } else {
      ASSERT_EQ(len, 0.0);
      if (!f.background[i]) ++invalid_fg;
    }
    background += f.background[i];
    background_with_normal += f.background[i] && f.normal_valid[i];
  }
  EXPECT_EQ(invalid_fg, s.invalid_normals);
  // Depth (and Position) come from the first sample, Normal is averaged over all samples: a
  // silhouette pixel whose first sample missed is background yet has a (short) normal. Only
  // such edge pixels may do that.
  EXPECT_LT(background_with_normal, background / 20);
}

TEST(CommittedScenes, CornellLightAndItsAllZeroWorld) {
  const io::Scene s = io::read_scene(exr("cornell"), everything());
  // 40 W area light of 0.5 x 0.5 m: L = P / (4 A) = 40 / 1 = 40 (white, so luminance 40).
  const scene::LightInfo* key = s.sidecar->light_for_group("ceiling_light");
  ASSERT_NE(key, nullptr);
  EXPECT_NEAR(key->luminance, 40.0, 1e-9);
  EXPECT_TRUE(key->in_frame.value_or(false));
  // The directly visible light renders exactly that radiance in the Emit pass.
  double emit_max = 0;
  for (std::size_t i = 0; i < s.frame.pixel_count(); ++i) emit_max = std::max(emit_max, lum(&s.frame.emission[3 * i]));
  EXPECT_NEAR(emit_max, 40.0, 40.0 * 1e-3);
  // The black world lights nothing: its group is flagged and reported.
  for (const auto& g : s.frame.light_groups) EXPECT_EQ(g.all_zero, g.name == "world") << g.name;
  EXPECT_NE(std::find(s.warnings.begin(), s.warnings.end(), "light group 'world' is zero in every pixel"),
            s.warnings.end());
}

TEST(CommittedScenes, TwoRoomsHidesItsLight) {
  const io::Scene s = io::read_scene(exr("two-rooms"), everything());
  const scene::Frame& f = s.frame;
  EXPECT_TRUE(std::all_of(f.emission.begin(), f.emission.end(), [](float v) { return v == 0.0f; }));
  double image_max = 0;
  for (std::size_t i = 0; i < f.pixel_count(); ++i) image_max = std::max(image_max, lum(&f.beauty[4 * i]));
  const scene::LightInfo* light = s.sidecar->light_for_group("room_b_light");
  ASSERT_NE(light, nullptr);
  // 300 W, 0.6 x 0.6 m: L = 300 / (4 * 0.36) = 208.33.
  EXPECT_NEAR(light->luminance, 300.0 / 1.44, 1e-9);
  EXPECT_FALSE(light->in_frame.value_or(true));
  EXPECT_LT(image_max * 10.0, light->luminance);
  const auto lit = std::find_if(f.light_groups.begin(), f.light_groups.end(),
                                [](const scene::LightGroupPlane& g) { return g.name == "room_b_light"; });
  ASSERT_NE(lit, f.light_groups.end());
  EXPECT_FALSE(lit->all_zero);
}

TEST(CommittedScenes, NightLampLuminanceFromItsStrength) {
  const io::Scene s = io::read_scene(exr("night"), everything());
  // Emission strength 3000, colour (1, 0.78, 0.45): Y = 3000 (0.2126 + 0.7152*0.78 + 0.0722*0.45).
  const scene::LightInfo* lamp = s.sidecar->light_for_group("lamp_1");
  ASSERT_NE(lamp, nullptr);
  EXPECT_NEAR(lamp->luminance, 2408.838, 1e-3);
  // A point light: 40 W, r = 0.03 m, colour (1, 0.6, 0.3): 40 / (4 pi^2 0.0009) * Y(colour).
  const scene::LightInfo* door = s.sidecar->light_for_group("door_lamp");
  ASSERT_NE(door, nullptr);
  EXPECT_NEAR(door->luminance, 40.0 / (4.0 * M_PI * M_PI * 0.0009) * (0.2126 + 0.7152 * 0.6 + 0.0722 * 0.3), 1e-6);
}

TEST(CommittedScenes, OnlyRequestedPassesAreRead) {
  io::SceneRequest r;
  r.required = Pass::Beauty;
  r.probe = r.sidecar = io::Companion::Skip;
  const io::Scene s = io::read_scene(exr("relief"), r);
  EXPECT_EQ(s.frame.beauty.size(), 4u * s.frame.pixel_count());
  EXPECT_TRUE(s.frame.position.empty());
  EXPECT_TRUE(s.frame.normal.empty());
  EXPECT_TRUE(s.frame.albedo.empty());
  EXPECT_TRUE(s.frame.depth.empty());
  EXPECT_TRUE(s.frame.light_groups.empty());
  EXPECT_FALSE(s.probe.has_value());
  EXPECT_FALSE(s.sidecar.has_value());
  // Yet the map knows where everything is.
  EXPECT_TRUE(s.channels.has(Pass::Position));
  EXPECT_EQ(s.channels.light_groups.size(), 2u);
}

TEST(CommittedScenes, AlbedoIsBoundedDiffuseColour) {
  io::SceneRequest r;
  r.required = Pass::Albedo | Pass::Depth;
  r.probe = r.sidecar = io::Companion::Skip;
  const scene::Frame f = io::read_scene(exr("cornell"), r).frame;
  for (std::size_t i = 0; i < 3 * f.pixel_count(); ++i) {
    ASSERT_GE(f.albedo[i], 0.0f);
    ASSERT_LE(f.albedo[i], 1.0f);
  }
}

TEST(CommittedScenes, BenchFrame1080p) {
  io::SceneRequest r;
  r.required = Pass::Beauty | scene::PassSet::gbuffer();
  r.probe = io::Companion::Skip;
  r.sidecar = io::Companion::Require;
  const io::Scene s = io::read_scene(kScenes + "bench/cornell-1080p.exr", r);
  EXPECT_EQ(s.frame.width, 1920);
  EXPECT_EQ(s.frame.height, 1080);
  // PXR24 keeps 24 bits of Blender's 1e10 background depth: still masked.
  const auto bg = std::count(s.frame.background.begin(), s.frame.background.end(), std::uint8_t(1));
  EXPECT_GT(bg, std::ptrdiff_t(s.frame.pixel_count() / 5));
  EXPECT_LT(bg, std::ptrdiff_t(s.frame.pixel_count() / 2));
}
