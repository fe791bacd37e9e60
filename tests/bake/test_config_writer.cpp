// Checks src/cgtmo/bake/config_writer.cpp: the written config reloads in OCIO 2.1 with the
// displays, views and looks the config promises, and a view equals its look over Standard.
#include <gtest/gtest.h>

#include <sstream>

#include "cgtmo/bake/choose.h"
#include "cgtmo/bake/config_writer.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;
using namespace cgtmo::bake;

namespace {
BakedLut reinhard_lut() {
  BakeSubject s = make_subject(operators::find_operator("reinhard"), {}, reference_scene_stats());
  Representation r;
  r.dims = 1;
  r.size = 1024;
  r.shaper = {-12, 16};
  return sample_lut(*s.exact, r);
}
}  // namespace

TEST(ConfigWriter, ReloadsWithDisplaysViewsAndLooks) {
  const BakedLut lut = reinhard_lut();
  ConfigView v{"reinhard", "test", &lut, "reinhard.spi1d"};
  auto config = build_config({v}, "../luts", "test config");
  std::istringstream text(config_text(config, "header line"));
  auto back = OCIO::Config::CreateFromStream(text);
  EXPECT_EQ(back->getMajorVersion(), 2u);
  EXPECT_EQ(back->getMinorVersion(), 1u);
  EXPECT_STREQ(back->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName(), "Linear Rec.709");
  // The names other tools default to (oiiotool's "linear", OCIO's lin_rec709) find the working space.
  for (const char* alias : {"Linear", "linear", "lin_rec709", "scene_linear"})
    ASSERT_TRUE(back->getColorSpace(alias)) << alias;
  for (const char* alias : {"Linear", "linear", "lin_rec709", "scene_linear"})
    EXPECT_STREQ(back->getColorSpace(alias)->getName(), "Linear Rec.709") << alias;
  for (const char* cs : {"ACEScg", "Linear Rec.2020", "Log2 Shaper", "Raw", "sRGB", "Rec.1886", "Display P3"})
    EXPECT_TRUE(back->getColorSpace(cs)) << cs;
  ASSERT_EQ(back->getNumDisplays(), 3);
  for (const char* d : {"sRGB", "Rec.1886", "Display P3"}) {
    ASSERT_EQ(back->getNumViews(d), 3) << d;
    EXPECT_STREQ(back->getView(d, 0), "Standard");
    EXPECT_STREQ(back->getView(d, 1), "reinhard");
    EXPECT_STREQ(back->getView(d, 2), "Raw");
    EXPECT_STREQ(back->getDisplayViewLooks(d, "reinhard"), "reinhard");
  }
  EXPECT_TRUE(back->getLook("reinhard"));
  EXPECT_TRUE(back->getLook("reinhard - +1 stop"));
  EXPECT_TRUE(back->getLook("Standard - -2 stops"));
  EXPECT_STREQ(back->getLook("reinhard")->getProcessSpace(), "Log2 Shaper");
}

TEST(ConfigWriter, ACEScgAndRec2020MatricesMapWhiteToWhite) {
  const BakedLut lut = reinhard_lut();
  auto config = build_config({}, ".", "test");
  for (const char* cs : {"ACEScg", "Linear Rec.2020", "ACES2065-1"}) {
    auto cpu = config->getProcessor(cs, "Linear Rec.709")->getDefaultCPUProcessor();
    float rgb[3] = {1, 1, 1};
    cpu->applyRGB(rgb);
    for (float c : rgb) EXPECT_NEAR(c, 1.0, 2e-3) << cs;  // both white points end at D65 white
  }
  // Rec.2020 green is outside Rec.709: its red becomes negative (-0.5876 by the published matrix).
  auto cpu = config->getProcessor("Linear Rec.2020", "Linear Rec.709")->getDefaultCPUProcessor();
  float g[3] = {0, 1, 0};
  cpu->applyRGB(g);
  EXPECT_NEAR(g[0], -0.5876, 2e-3);
  EXPECT_NEAR(g[1], 1.1329, 2e-3);
  // D65 white in XYZ (0.9505, 1, 1.0891) is Rec.709 white.
  auto xyz = config->getProcessor("CIE-XYZ-D65", "Linear Rec.709")->getDefaultCPUProcessor();
  float w[3] = {0.95047f, 1.0f, 1.08883f};
  xyz->applyRGB(w);
  for (float c : w) EXPECT_NEAR(c, 1.0, 1e-3);
}
