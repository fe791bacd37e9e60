// src/cgtmo/io/exr_luma_chroma.cpp: luminance/chroma OpenEXR files (Y, RY, BY subsampled 2x2, as
// OpenEXR's RgbaOutputFile writes them with WRITE_YC / WRITE_YCA) read as RGB(A) by every reader.
// The images have one hue and varying brightness: the chroma of every pixel is then the same,
// so subsampling loses nothing and the RGB read back must match the RGB written up to half-float
// rounding of Y, RY and BY (a few 1e-4 relative; the test allows 2e-3).
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "support/exr_writer.h"

using namespace cgtmo;

namespace {

constexpr float kHue[3] = {0.8f, 0.4f, 0.2f};

float brightness(int x, int y) { return 0.5f + 0.25f * float(x) + 0.5f * float(y); }

// A w x h image with data window at (ox, oy) in a display window of (0,0) dw x dh.
void write_yc(const std::string& path, int ox, int oy, int w, int h, int dw, int dh, Imf::RgbaChannels channels) {
  const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(dw - 1, dh - 1));
  const Imath::Box2i data(Imath::V2i(ox, oy), Imath::V2i(ox + w - 1, oy + h - 1));
  Imf::RgbaOutputFile out(path.c_str(), display, data, channels);
  // Full half precision: by default OpenEXR rounds luminance to 7 and chroma to 5 significand
  // bits, a loss of about 1% here that would hide a reader error of the same size.
  out.setYCRounding(10, 10);
  std::vector<Imf::Rgba> px(std::size_t(w) * std::size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float s = brightness(ox + x, oy + y);
      px[std::size_t(y) * std::size_t(w) + std::size_t(x)] = Imf::Rgba(s * kHue[0], s * kHue[1], s * kHue[2], 0.75f);
    }
  out.setFrameBuffer(px.data() - ox - std::ptrdiff_t(oy) * w, 1, std::size_t(w));
  out.writePixels(h);
}

}  // namespace

TEST(LumaChroma, ReadAsRgbThroughEveryReader) {
  test::TempDir dir;
  const std::string path = dir.file("yc.exr");
  write_yc(path, 0, 0, 16, 8, 16, 8, Imf::WRITE_YC);
  EXPECT_TRUE(io::is_luma_chroma_exr(path));
  const io::FileChannels fc = io::read_header(path);
  EXPECT_EQ(fc.width, 16);
  EXPECT_EQ(fc.names, (std::vector<std::string>{"R", "G", "B"}));

  const scene::Frame f = io::read_beauty(path, "");
  ASSERT_EQ(f.width, 16);
  ASSERT_EQ(f.height, 8);
  ASSERT_EQ(f.channels, 3);
  double worst = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) {
        const double want = brightness(x, y) * kHue[c];
        worst = std::max(worst, std::abs(f.beauty[(std::size_t(y) * 16 + std::size_t(x)) * 3 + std::size_t(c)] - want) / want);
      }
  EXPECT_LT(worst, 2e-3);
}

TEST(LumaChroma, AlphaAndWindowsAreKept) {
  test::TempDir dir;
  const std::string path = dir.file("yca.exr");
  // Auto-cropped: a 6x4 data window at (2,2) of a 10x8 frame.
  write_yc(path, 2, 2, 6, 4, 10, 8, Imf::WRITE_YCA);
  io::SceneRequest r;
  r.probe = r.sidecar = io::Companion::Skip;
  const io::Scene s = io::read_scene(path, r);
  ASSERT_EQ(s.frame.width, 10);
  ASSERT_EQ(s.frame.height, 8);
  ASSERT_EQ(s.frame.channels, 4);
  const float* inside = &s.frame.beauty[(3 * 10 + 4) * 4];
  EXPECT_NEAR(inside[1], brightness(4, 3) * kHue[1], 2e-3 * brightness(4, 3));
  EXPECT_EQ(inside[3], 0.75f);
  EXPECT_EQ(s.frame.beauty[0], 0.0f);  // outside the data window
  EXPECT_EQ(s.frame.beauty[3], 0.0f);
  r.read.window = io::Window::Data;
  EXPECT_EQ(io::read_scene(path, r).frame.width, 6);
}

TEST(LumaChroma, PlainRgbFilesAreNotTakenForLumaChroma) {
  test::TempDir dir;
  const std::string path = dir.file("rgb.exr");
  write_yc(path, 0, 0, 4, 4, 4, 4, Imf::WRITE_RGB);
  EXPECT_FALSE(io::is_luma_chroma_exr(path));
  test::write_text(dir.file("x.png"), "not an image");
  EXPECT_FALSE(io::is_luma_chroma_exr(dir.file("x.png")));
}
