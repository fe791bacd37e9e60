// src/cgtmo/io/exr_luma_chroma.cpp: luminance/chroma OpenEXR files (Y, RY, BY subsampled 2x2, as
// OpenEXR's RgbaOutputFile writes them with WRITE_YC / WRITE_YCA) read as RGB(A) by every reader.
// The images have one hue and varying brightness: the chroma of every pixel is then the same,
// so subsampling loses nothing and the RGB read back must match the RGB written up to half-float
// rounding of Y, RY and BY (a few 1e-4 relative; the test allows 2e-3).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
#include "support/error_of.h"
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

namespace {

// A 4x2 half image with the channels and samplings given, through OpenEXR's general interface.
void write_sampled(const std::string& path, const std::vector<std::pair<std::string, int>>& x_samplings) {
  Imf::Header header(4, 2);
  for (const auto& [name, xs] : x_samplings) header.channels().insert(name, Imf::Channel(Imf::HALF, xs, xs == 1 ? 1 : 2));
  Imf::OutputFile out(path.c_str(), header);
  std::vector<std::vector<half>> planes;
  Imf::FrameBuffer fb;
  for (const auto& [name, xs] : x_samplings) {
    planes.emplace_back(8, half(0.5f));
    fb.insert(name, Imf::Slice::Make(Imf::HALF, planes.back().data(), Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(3, 1)),
                                     sizeof(half), 0, xs, xs == 1 ? 1 : 2));
  }
  out.setFrameBuffer(fb);
  out.writePixels(2);
}

}  // namespace

// Subsampling other than the luminance/chroma layout: no reader of cgtmo takes it, so the header
// readers refuse it too (found by fuzz_exr_header: a 4x2 file whose B channel was sampled 2x1 and
// whose header held a second channel list was shown as "luminance/chroma, read as RGB, 3
// channels", then refused at the first pixel read; the header's own count was 4 channels).
TEST(LumaChroma, OtherSubsampledChannelsAreRefusedByEveryReader) {
  test::TempDir dir;
  const std::string seed = std::string(CGTMO_SOURCE_DIR) + "/tests/fuzz/corpus/exr_header/regression-luma-chroma-subsampled-b.exr";
  EXPECT_FALSE(io::is_luma_chroma_exr(seed));
  EXPECT_EQ(test::error_of<DataError>([&] { io::read_header(seed); }),
            "'" + seed + "': channel 'B' is sampled 2x1: subsampled channels are read only as OpenEXR's luminance/chroma "
                         "layout in the first part (Y; RY, BY at 2x2; A)");
  const std::string b = dir.file("b.exr"), extra = dir.file("yc_z.exr");
  write_sampled(b, {{"R", 1}, {"G", 1}, {"B", 2}});
  write_sampled(extra, {{"Y", 1}, {"RY", 2}, {"BY", 2}, {"Z", 1}});  // RgbaInputFile would drop Z
  for (const std::string& path : {b, extra}) {
    const std::string e = test::error_of<DataError>([&] { io::read_header(path); });
    EXPECT_NE(e.find("subsampled channels are read only as OpenEXR's luminance/chroma layout"), std::string::npos) << e;
    EXPECT_EQ(test::error_of<DataError>([&] { io::read_parts(path); }), e);
    EXPECT_EQ(test::error_of<DataError>([&] { io::read_beauty(path, ""); }), e);
  }
  // The layout itself, with or without alpha: the header's declaration and the reader agree.
  const std::string ok = dir.file("yca.exr");
  write_sampled(ok, {{"Y", 1}, {"RY", 2}, {"BY", 2}, {"A", 1}});
  io::ExrDeclaration d;
  ASSERT_TRUE(io::read_exr_declaration(ok, &d));
  const io::FileChannels fc = io::read_header(ok);
  EXPECT_EQ(std::size_t(d.parts[0].channels), fc.names.size());
  EXPECT_EQ(d.parts[0].width, fc.width);
  EXPECT_EQ(d.parts[0].height, fc.height);
}

TEST(LumaChroma, PlainRgbFilesAreNotTakenForLumaChroma) {
  test::TempDir dir;
  const std::string path = dir.file("rgb.exr");
  write_yc(path, 0, 0, 4, 4, 4, 4, Imf::WRITE_RGB);
  EXPECT_FALSE(io::is_luma_chroma_exr(path));
  test::write_text(dir.file("x.png"), "not an image");
  EXPECT_FALSE(io::is_luma_chroma_exr(dir.file("x.png")));
}
