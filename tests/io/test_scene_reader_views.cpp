// src/cgtmo/io/scene_reader.cpp on multi-view (stereo) OpenEXR files: one part whose multiView
// attribute lists the views (the default view's channels unprefixed, the others' as right.R), and
// one part per view (the view attribute). Each view's pixels hold a value of its own.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <functional>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "support/error_of.h"
#include "support/exr_writer.h"

using namespace cgtmo;
using scene::Pass;

namespace {

io::SceneRequest in_view(const std::string& view) {
  io::SceneRequest r;
  r.optional = Pass::Depth;
  r.probe = r.sidecar = io::Companion::Skip;
  r.read.view = view;
  return r;
}

// One part, views left (default, unprefixed) and right: left's pixels 1 (depth 10), right's 2 (20).
void write_single_part(const std::string& path) {
  OIIO::ImageSpec s(4, 2, 8, OIIO::TypeDesc::FLOAT);
  s.channelnames = {"R", "G", "B", "Z", "right.R", "right.G", "right.B", "right.Z"};
  s.alpha_channel = -1;
  s.z_channel = -1;
  const char* views[] = {"left", "right"};
  s.attribute("multiView", OIIO::TypeDesc(OIIO::TypeDesc::STRING, 2), views);
  std::vector<float> px;
  for (int i = 0; i < 8; ++i)
    for (float v : {1.f, 1.f, 1.f, 10.f, 2.f, 2.f, 2.f, 20.f}) px.push_back(v);
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out->open(path, s)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
  out->close();
}

}  // namespace

TEST(SceneReaderViews, OnePartDefaultViewAndANamedOne) {
  test::TempDir dir;
  const std::string path = dir.file("stereo.exr");
  write_single_part(path);
  const io::Scene left = io::read_scene(path, in_view(""));
  EXPECT_EQ(left.views, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(left.view, "left");
  EXPECT_EQ(left.frame.beauty[0], 1.0f);
  EXPECT_EQ(left.frame.depth[0], 10.0f);
  const io::Scene right = io::read_scene(path, in_view("right"));
  EXPECT_EQ(right.view, "right");
  EXPECT_EQ(right.frame.beauty[0], 2.0f);
  EXPECT_EQ(right.frame.depth[7], 20.0f);
  EXPECT_EQ(right.channels.beauty, (std::vector<std::string>{"R", "G", "B"}));
  // The beauty-only reader of the global operators too.
  EXPECT_EQ(io::read_beauty(path, "", io::ReadOptions{io::Window::Display, "right", {}}).beauty[5], 2.0f);
  EXPECT_EQ(cgtmo::test::error_of([&] { io::read_scene(path, in_view("centre")); }),
            "'" + path + "': no view 'centre' (views: left, right)");
}

TEST(SceneReaderViews, OnePartPerView) {
  test::TempDir dir;
  const std::string path = dir.file("parts.exr");
  test::PartSpec l, r;
  for (test::PartSpec* p : {&l, &r}) {
    p->width = 4;
    p->height = 2;
    p->names = {"R", "G", "B"};
    p->pixels.assign(24, p == &l ? 1.0f : 2.0f);
  }
  l.part_name = "left";
  r.part_name = "right";
  // exr_writer has no view attribute: add it through OpenImageIO here.
  std::vector<OIIO::ImageSpec> specs;
  for (const test::PartSpec* p : {&l, &r}) {
    OIIO::ImageSpec s(4, 2, 3, OIIO::TypeDesc::FLOAT);
    s.channelnames = p->names;
    s.attribute("name", p->part_name);
    s.attribute("view", p->part_name);
    specs.push_back(s);
  }
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out->open(path, 2, specs.data())) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, l.pixels.data())) << out->geterror();
  ASSERT_TRUE(out->open(path, specs[1], OIIO::ImageOutput::AppendSubimage)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, r.pixels.data())) << out->geterror();
  out->close();

  EXPECT_EQ(io::read_scene(path, in_view("")).frame.beauty[0], 1.0f);
  const io::Scene right = io::read_scene(path, in_view("right"));
  EXPECT_EQ(right.views, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(right.frame.beauty[0], 2.0f);
}

TEST(SceneReaderViews, AViewOfAFileWithoutViews) {
  test::TempDir dir;
  test::PartSpec p;
  p.width = 2;
  p.height = 2;
  p.names = {"R", "G", "B"};
  test::write_exr(dir.file("plain.exr"), {p});
  EXPECT_TRUE(io::read_scene(dir.file("plain.exr"), in_view("")).views.empty());
  EXPECT_NE(cgtmo::test::error_of([&] { io::read_scene(dir.file("plain.exr"), in_view("left")); }).find("not multi-view"), std::string::npos);
}
