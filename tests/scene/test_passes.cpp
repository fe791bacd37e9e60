// src/cgtmo/scene/passes.cpp: pass sets and the mapping of Blender's and generic channel names.
#include "cgtmo/scene/passes.h"

#include <gtest/gtest.h>

#include "cgtmo/errors.h"

using namespace cgtmo;
using namespace cgtmo::scene;
using Names = std::vector<std::string>;

// The channel list Blender 3.4 wrote for tests/scenes/cornell (file order, as oiiotool lists it).
static const Names kBlender = {
    "ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A",
    "ViewLayer.Combined_ceiling_light.R", "ViewLayer.Combined_ceiling_light.G", "ViewLayer.Combined_ceiling_light.B",
    "ViewLayer.Combined_world.R", "ViewLayer.Combined_world.G", "ViewLayer.Combined_world.B", "ViewLayer.Depth.Z",
    "ViewLayer.DiffCol.R", "ViewLayer.DiffCol.G", "ViewLayer.DiffCol.B", "ViewLayer.Emit.R", "ViewLayer.Emit.G",
    "ViewLayer.Emit.B", "ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z", "ViewLayer.Position.X",
    "ViewLayer.Position.Y", "ViewLayer.Position.Z"};

TEST(PassSet, CombinesAndTests) {
  const PassSet s = Pass::Beauty | Pass::Normal;
  EXPECT_TRUE(s.has(Pass::Beauty));
  EXPECT_TRUE(s.has(Pass::Normal));
  EXPECT_FALSE(s.has(Pass::Position));
  EXPECT_EQ(describe(s), "beauty, normal");
  EXPECT_EQ(describe(PassSet()), "none");
  EXPECT_FALSE((s - Pass::Normal).has(Pass::Normal));
  EXPECT_EQ(describe(PassSet::gbuffer()), "depth, position, normal, albedo");
}

TEST(PassSet, ParsesNames) {
  EXPECT_EQ(parse_passes("normal,Position").bits(), (Pass::Normal | Pass::Position).bits());
  EXPECT_EQ(parse_passes("gbuffer").bits(), PassSet::gbuffer().bits());
  EXPECT_EQ(parse_passes("all").bits(), PassSet::all().bits());
  EXPECT_THROW(parse_passes("normals,uv"), UsageError);
}

TEST(MapChannels, BlenderMultilayer) {
  const ChannelMap m = map_channels(kBlender, "ViewLayer.Combined");
  EXPECT_EQ(m.scheme, "blender");
  EXPECT_EQ(m.beauty, (Names{"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A"}));
  EXPECT_EQ(m.position, (Names{"ViewLayer.Position.X", "ViewLayer.Position.Y", "ViewLayer.Position.Z"}));
  EXPECT_EQ(m.normal, (Names{"ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z"}));
  EXPECT_EQ(m.albedo, (Names{"ViewLayer.DiffCol.R", "ViewLayer.DiffCol.G", "ViewLayer.DiffCol.B"}));
  EXPECT_EQ(m.emission, (Names{"ViewLayer.Emit.R", "ViewLayer.Emit.G", "ViewLayer.Emit.B"}));
  EXPECT_EQ(m.depth, "ViewLayer.Depth.Z");
  ASSERT_EQ(m.light_groups.size(), 2u);
  EXPECT_EQ(m.light_groups[0].name, "ceiling_light");
  EXPECT_EQ(m.light_groups[0].rgb[2], "ViewLayer.Combined_ceiling_light.B");
  EXPECT_EQ(m.light_groups[1].name, "world");
  EXPECT_TRUE(unmapped_channels(kBlender, m).empty());
  // Only the channels of the passes asked for.
  EXPECT_EQ(m.channels_for(Pass::Depth | Pass::Normal),
            (Names{"ViewLayer.Depth.Z", "ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z"}));
}

TEST(MapChannels, BlenderDenoisingAlbedoIsNotTheAlbedo) {
  // docs/platform.md: Denoising Albedo includes emission and mirror reflections; only DiffCol is albedo.
  const Names names = {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
                       "ViewLayer.Denoising Albedo.R", "ViewLayer.Denoising Albedo.G", "ViewLayer.Denoising Albedo.B"};
  const ChannelMap m = map_channels(names, "ViewLayer.Combined");
  EXPECT_TRUE(m.albedo.empty());
  EXPECT_EQ(unmapped_channels(names, m).size(), 3u);
}

TEST(MapChannels, GenericNamesAnyCase) {
  const Names names = {"R", "G", "B", "A", "P.x", "P.y", "P.z", "N.X", "N.Y", "N.Z", "albedo.r", "albedo.g",
                       "albedo.b", "Z", "lightgroup.key.R", "lightgroup.key.G", "lightgroup.key.B", "uv.u"};
  const ChannelMap m = map_channels(names, "");
  EXPECT_EQ(m.scheme, "generic");
  EXPECT_EQ(m.beauty, (Names{"R", "G", "B", "A"}));
  EXPECT_EQ(m.position, (Names{"P.x", "P.y", "P.z"}));
  EXPECT_EQ(m.normal, (Names{"N.X", "N.Y", "N.Z"}));
  EXPECT_EQ(m.albedo, (Names{"albedo.r", "albedo.g", "albedo.b"}));
  EXPECT_EQ(m.depth, "Z");
  ASSERT_EQ(m.light_groups.size(), 1u);
  EXPECT_EQ(m.light_groups[0].name, "key");
  EXPECT_EQ(unmapped_channels(names, m), (Names{"uv.u"}));
}

TEST(MapChannels, GenericLongNamesBesideALayer) {
  const Names names = {"beauty.R", "beauty.G", "beauty.B", "position.x", "position.y", "position.z",
                       "normal.x", "normal.y", "normal.z", "depth"};
  const ChannelMap m = map_channels(names, "beauty");
  EXPECT_EQ(m.position, (Names{"position.x", "position.y", "position.z"}));
  EXPECT_EQ(m.normal, (Names{"normal.x", "normal.y", "normal.z"}));
  EXPECT_EQ(m.depth, "depth");
  EXPECT_TRUE(m.albedo.empty());
  EXPECT_FALSE(m.has(Pass::Albedo));
}

TEST(MapChannels, IncompleteTriplesAreMissing) {
  const Names names = {"R", "G", "B", "P.x", "P.y", "lightgroup.fill.R", "lightgroup.fill.G"};
  const ChannelMap m = map_channels(names, "");
  EXPECT_FALSE(m.has(Pass::Position));
  EXPECT_FALSE(m.has(Pass::LightGroups));
  const std::string expected = ChannelMap::expected_names(Pass::Position, "");
  EXPECT_NE(expected.find("P.X,Y,Z"), std::string::npos) << expected;
}

// --pass role=LAYER: names the automatic mapping does not know (made up here, like any renderer's
// own spellings), and an override of a pass it did find.
static const Names kOther = {"R", "G", "B", "wpos.x", "wpos.y", "wpos.z", "nrm.r", "nrm.g", "nrm.b", "dif.R", "dif.G",
                             "dif.B", "camdist", "keyL.R", "keyL.G", "keyL.B", "Z"};

TEST(PassOverrides, PointRolesAtLayersTheMappingDoesNotKnow) {
  ChannelMap m = map_channels(kOther, "");
  EXPECT_FALSE(m.has(Pass::Position));
  EXPECT_EQ(m.depth, "Z");
  apply_overrides(m, kOther,
                  {parse_pass_override("position=wpos"), parse_pass_override("normal=nrm"), parse_pass_override("albedo=dif"),
                   parse_pass_override("depth=camdist"), parse_pass_override("lightgroup:Key=keyL")},
                  "f.exr");
  EXPECT_EQ(m.position, (Names{"wpos.x", "wpos.y", "wpos.z"}));
  EXPECT_EQ(m.normal, (Names{"nrm.r", "nrm.g", "nrm.b"}));
  EXPECT_EQ(m.albedo, (Names{"dif.R", "dif.G", "dif.B"}));
  EXPECT_EQ(m.depth, "camdist");  // replaces the Z the mapping found
  ASSERT_EQ(m.light_groups.size(), 1u);
  EXPECT_EQ(m.light_groups[0].name, "Key");
  EXPECT_EQ(m.light_groups[0].rgb, (Names{"keyL.R", "keyL.G", "keyL.B"}));
  EXPECT_TRUE(unmapped_channels(kOther, m) == Names{"Z"});
}

TEST(PassOverrides, BadOverridesSayWhatIsWrong) {
  auto usage = [](const std::string& text) {
    try {
      parse_pass_override(text);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(usage("colour=wpos").find("use ROLE=LAYER"), std::string::npos);
  EXPECT_NE(usage("position").find("use ROLE=LAYER"), std::string::npos);
  EXPECT_NE(usage("position=").find("use ROLE=LAYER"), std::string::npos);
  EXPECT_NE(usage("lightgroup:=x").find("use ROLE=LAYER"), std::string::npos);
  ChannelMap m = map_channels(kOther, "");
  try {
    apply_overrides(m, kOther, {parse_pass_override("normal=nothere")}, "f.exr");
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_EQ(std::string(e.what()), "'f.exr': --pass normal=nothere: no channels nothere.X,Y,Z or nothere.R,G,B");
  }
}
