// src/cgtmo/io/scene_reader.cpp and exr_parts.cpp on OpenEXR windows: data windows larger than the
// display window (overscan), smaller (auto-crop), with negative origins, and parts whose data
// windows differ (a depth part smaller than the beauty). Every pixel written holds a value made
// from its absolute image-plane coordinates, so where it lands after reading is checked against
// the coordinates, not against the reader's own arithmetic.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/scene_reader.h"
#include "support/error_of.h"
#include "support/exr_writer.h"

using namespace cgtmo;
using scene::Pass;
using test::PartSpec;

namespace {

// Channel c of the pixel at image-plane (x, y): unique for the small windows used here.
float coded(int x, int y, std::size_t c) { return 1000.0f + 100.0f * float(c) + 10.0f * float(y) + float(x); }

PartSpec coded_part(const std::vector<std::string>& names, int x, int y, int w, int h) {
  PartSpec p;
  p.names = names;
  p.x = x;
  p.y = y;
  p.width = w;
  p.height = h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (std::size_t c = 0; c < names.size(); ++c) p.pixels.push_back(coded(x + i, y + j, c));
  return p;
}

io::SceneRequest request(io::Window w, scene::PassSet optional = {}) {
  io::SceneRequest r;
  r.optional = optional;
  r.probe = r.sidecar = io::Companion::Skip;
  r.read.window = w;
  return r;
}

}  // namespace

TEST(SceneReaderWindows, OverscanReadsTheDisplayWindowOrAllTheData) {
  // 2 pixels of overscan left and right, 1 above and below a 4x2 frame: data (-2,-1) 8x4.
  test::TempDir dir;
  PartSpec p = coded_part({"R", "G", "B"}, -2, -1, 8, 4);
  p.full_x = 0, p.full_y = 0, p.full_width = 4, p.full_height = 2;
  test::write_exr(dir.file("over.exr"), {p});

  const io::Scene d = io::read_scene(dir.file("over.exr"), request(io::Window::Display));
  ASSERT_EQ(d.frame.width, 4);
  ASSERT_EQ(d.frame.height, 2);
  EXPECT_EQ(d.window, (io::Rect{0, 0, 4, 2}));
  EXPECT_EQ(d.data_window, (io::Rect{-2, -1, 8, 4}));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)
      for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(d.frame.beauty[(std::size_t(y) * 4 + std::size_t(x)) * 3 + c], coded(x, y, c));

  const io::Scene a = io::read_scene(dir.file("over.exr"), request(io::Window::Data));
  ASSERT_EQ(a.frame.width, 8);
  ASSERT_EQ(a.frame.height, 4);
  EXPECT_EQ(a.frame.beauty[0], coded(-2, -1, 0));
  EXPECT_EQ(a.frame.beauty.back(), coded(5, 2, 2));

  // The beauty-only reader of the global operators takes the same window.
  EXPECT_EQ(io::read_beauty(dir.file("over.exr"), "").width, 4);
  EXPECT_EQ(io::read_beauty(dir.file("over.exr"), "", io::ReadOptions{io::Window::Data, "", {}}).width, 8);
}

TEST(SceneReaderWindows, AutoCropIsPaddedWithZeroAndBackgroundDepth) {
  // A 6x4 frame whose only non-empty pixels (a 2x2 block at (3,1)) were all that was stored.
  test::TempDir dir;
  PartSpec p = coded_part({"R", "G", "B", "A", "Z"}, 3, 1, 2, 2);
  p.full_width = 6, p.full_height = 4;
  test::write_exr(dir.file("crop.exr"), {p});

  const io::Scene d = io::read_scene(dir.file("crop.exr"), request(io::Window::Display, Pass::Depth));
  const scene::Frame& f = d.frame;
  ASSERT_EQ(f.width, 6);
  ASSERT_EQ(f.height, 4);
  ASSERT_EQ(f.channels, 4);
  std::size_t background = 0;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) {
      const std::size_t i = std::size_t(y) * 6 + std::size_t(x);
      const bool inside = x >= 3 && x < 5 && y >= 1 && y < 3;
      for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(f.beauty[i * 4 + c], inside ? coded(x, y, c) : 0.0f) << x << "," << y;
      EXPECT_EQ(f.depth[i], inside ? coded(x, y, 4) : 1e10f);
      EXPECT_EQ(f.background[i], inside ? 0 : 1);
      background += f.background[i];
    }
  EXPECT_EQ(background, 24u - 4u);

  const io::Scene a = io::read_scene(dir.file("crop.exr"), request(io::Window::Data, Pass::Depth));
  ASSERT_EQ(a.frame.width, 2);
  ASSERT_EQ(a.frame.height, 2);
  EXPECT_EQ(a.frame.beauty[0], coded(3, 1, 0));
  EXPECT_EQ(a.frame.depth[3], coded(4, 2, 4));
}

TEST(SceneReaderWindows, NegativeOriginDisplayWindow) {
  test::TempDir dir;
  PartSpec p = coded_part({"R", "G", "B"}, -3, -2, 4, 2);
  p.full_x = -3, p.full_y = -2, p.full_width = 4, p.full_height = 2;
  test::write_exr(dir.file("neg.exr"), {p});
  for (io::Window w : {io::Window::Display, io::Window::Data}) {
    const io::Scene s = io::read_scene(dir.file("neg.exr"), request(w));
    ASSERT_EQ(s.frame.width, 4);
    ASSERT_EQ(s.frame.height, 2);
    EXPECT_EQ(s.frame.beauty[0], coded(-3, -2, 0));
    EXPECT_EQ(s.frame.beauty[(1 * 4 + 3) * 3 + 1], coded(0, -1, 1));
  }
}

TEST(SceneReaderWindows, PartsWithDifferentDataWindows) {
  // A beauty part 5x4 and a depth/normal part covering only (1,1) 3x2, as a renderer that
  // crops its utility passes writes it.
  test::TempDir dir;
  PartSpec beauty = coded_part({"R", "G", "B"}, 0, 0, 5, 4);
  beauty.part_name = "beauty";
  PartSpec utility = coded_part({"Z", "N.x", "N.y", "N.z"}, 1, 1, 3, 2);
  utility.part_name = "utility";
  test::write_exr(dir.file("parts.exr"), {beauty, utility});

  const io::Scene s = io::read_scene(dir.file("parts.exr"), request(io::Window::Display, Pass::Depth | Pass::Normal));
  const scene::Frame& f = s.frame;
  ASSERT_EQ(f.width, 5);
  ASSERT_EQ(f.height, 4);
  ASSERT_EQ(f.depth.size(), 20u);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) {
      const std::size_t i = std::size_t(y) * 5 + std::size_t(x);
      const bool inside = x >= 1 && x < 4 && y >= 1 && y < 3;
      EXPECT_EQ(f.depth[i], inside ? coded(x, y, 0) : 1e10f) << x << "," << y;
      EXPECT_EQ(f.background[i], inside ? 0 : 1);
      EXPECT_EQ(f.normal_valid[i], inside ? 1 : 0);
      EXPECT_EQ(f.beauty[i * 3], coded(x, y, 0));
    }
  // Outside the depth part is background, so its missing normals are not counted as foreground.
  EXPECT_EQ(s.invalid_normals, 0u);
}

TEST(SceneReaderWindows, DisplayWindowBeyondTheMemoryBudgetIsRefused) {
  // A few stored pixels in a display window of 60000x60000: reading it as float32 would need
  // 43 GB, refused before anything is allocated.
  test::TempDir dir;
  PartSpec p = coded_part({"R", "G", "B"}, 0, 0, 2, 2);
  p.full_width = 60000, p.full_height = 60000;
  test::write_exr(dir.file("huge.exr"), {p});
  io::set_memory_budget(std::uint64_t(256) << 20);
  const std::string e = cgtmo::test::error_of([&] { io::read_scene(dir.file("huge.exr"), request(io::Window::Display)); });
  io::set_memory_budget(0);
  EXPECT_NE(e.find("60000x60000"), std::string::npos) << e;
  EXPECT_NE(e.find("memory budget"), std::string::npos) << e;
  // Its data window alone reads.
  EXPECT_EQ(io::read_scene(dir.file("huge.exr"), request(io::Window::Data)).frame.width, 2);
}
