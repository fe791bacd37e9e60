// pipeline::Applier (what `cgtmo apply` and the Python module run) on luminance/chroma OpenEXR
// files as OpenEXR's RgbaOutputFile writes them with WRITE_YC: Y at full resolution, RY and BY
// at half resolution both ways, with its default rounding (Y to 7 significand bits, RY and BY to 5).
// The same RGB written as plain half RGB is the reference: the two outputs may differ only by what
// the format loses (docs/exr-inputs.md).
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfRgbaFile.h>
#include <ImfStandardAttributes.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cgtmo/io/image_io.h"
#include "cgtmo/pipeline/apply_file.h"
#include "support/exr_writer.h"

namespace cgtmo::pipeline {
namespace {

constexpr int kW = 64, kH = 48;

// Colour over 2^-5 .. 2^5, brightness rising down the frame, hue turning by 2 radians across it
// and still at both edges: OpenEXR rebuilds the chroma of an edge from its side alone, which on
// a hue that changes there costs up to 11 code values (not cgtmo's to lose or keep).
std::vector<Imf::Rgba> source() {
  std::vector<Imf::Rgba> px;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double h = 1.0 - std::cos(3.14159265 * x / (kW - 1)), s = std::exp2(-5.0 + 10.0 * y / (kH - 1));
      px.emplace_back(float(s * (0.55 + 0.45 * std::cos(h))), float(s * (0.55 + 0.45 * std::cos(h - 2.0944))),
                      float(s * (0.55 + 0.45 * std::cos(h + 2.0944))), 1.f);
    }
  return px;
}

void write(const std::string& path, Imf::RgbaChannels channels, const std::vector<Imf::Rgba>& px) {
  Imf::Header header(kW, kH);
  Imf::addChromaticities(header, Imf::Chromaticities());  // Rec.709, as the RGB reference says too
  Imf::RgbaOutputFile out(path.c_str(), header, channels);
  out.setFrameBuffer(px.data(), 1, kW);
  out.writePixels(kH);
}

std::vector<int> read8(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path;
  std::vector<unsigned char> px(std::size_t(kW) * kH * 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
  return std::vector<int>(px.begin(), px.end());
}

std::vector<float> read_float(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path;
  std::vector<float> px(std::size_t(kW) * kH * 3);
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
  return px;
}

// What the format may lose of one pixel (c, Y: a channel and the luminance): Y rounded to 7
// significand bits (2^-8 of Y), RY = (R - Y) / Y and BY to 5 (2^-6 of R - Y, B - Y), and 2^-8 of
// the values for the half-float storage and the 2x2 chroma of this slowly turning hue (a margin
// found here: at 2^-10 the red of a green where the hue turns fastest was 12% over).
double loss(double c, double y) { return std::ldexp(std::abs(c - y), -6) + std::ldexp(c, -8) + std::ldexp(c + y, -8); }

}  // namespace

// Through the whole apply with the identity operator and no display encoding, the pixels read
// back are the RGB the file was made from, within what the format loses.
TEST(ApplyLumaChroma, ReadsTheRgbItWasMadeFromWithinTheFormatsLoss) {
  ::unsetenv("OCIO");
  test::TempDir dir;
  const std::vector<Imf::Rgba> px = source();
  const std::string yc = dir.file("yc.exr"), out = dir.file("out.exr");
  write(yc, Imf::WRITE_YC, px);
  {
    Imf::RgbaInputFile check(yc.c_str());
    ASSERT_EQ(check.header().channels().findChannel("RY")->xSampling, 2);  // really subsampled
  }
  ApplyOptions o;
  o.op = "linear";  // exposure, then the identity below 1
  o.exposure_ev = -6;
  o.encode_display = false;
  const ApplyReport rep = Applier(o).apply_file(yc, out);
  EXPECT_EQ(rep.width, kW);
  EXPECT_EQ(rep.channels, 3);
  const std::vector<float> got = read_float(out);
  const double wr = 0.2126, wb = 0.0722, wg = 1 - wr - wb, k = std::ldexp(1.0, -6);
  double worst = 0;  // of error / loss
  for (std::size_t i = 0; i < px.size(); ++i) {
    const double r = k * float(px[i].r), g = k * float(px[i].g), b = k * float(px[i].b), y = wr * r + wg * g + wb * b;
    const double lr = loss(r, y), lb = loss(b, y), lg = (std::ldexp(y, -8) + wr * lr + wb * lb) / wg + std::ldexp(g + y, -10);
    const double e[3] = {std::abs(got[i * 3] - r) / lr, std::abs(got[i * 3 + 1] - g) / lg, std::abs(got[i * 3 + 2] - b) / lb};
    worst = std::max({worst, e[0], e[1], e[2]});
  }
  EXPECT_LE(worst, 1.0);
  EXPECT_GT(worst, 0.05);  // the loss is there: this is the luminance/chroma file, not an RGB one
}

// The display-encoded outputs of a luminance/chroma file and of the same RGB written as RGB.
TEST(ApplyLumaChroma, DisplayOutputsAgreeWithTheRgbFilesWithinTheFormatsLoss) {
  ::unsetenv("OCIO");
  test::TempDir dir;
  const std::vector<Imf::Rgba> px = source();
  const std::string yc = dir.file("yc.exr"), rgb = dir.file("rgb.exr");
  write(yc, Imf::WRITE_YC, px);
  write(rgb, Imf::WRITE_RGB, px);
  {
    Imf::RgbaInputFile check(yc.c_str());
    ASSERT_EQ(check.header().channels().findChannel("RY")->xSampling, 2);  // really subsampled
  }
  for (const char* op : {"reinhard", "agx", "drago"}) {
    ApplyOptions o;
    o.op = op;
    std::vector<std::string> warnings;
    o.warn = [&](const std::string& w) { warnings.push_back(w); };
    const Applier a(o);
    const ApplyReport rep = a.apply_file(yc, dir.file(std::string(op) + "-yc.png"));
    a.apply_file(rgb, dir.file(std::string(op) + "-rgb.png"));
    EXPECT_EQ(rep.channels, 3);
    EXPECT_NE(rep.input_space.find("chromaticities attribute"), std::string::npos) << rep.input_space;
    EXPECT_TRUE(warnings.empty());
    const std::vector<int> got = read8(dir.file(std::string(op) + "-yc.png")), want = read8(dir.file(std::string(op) + "-rgb.png"));
    int worst = 0;
    double mean = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      worst = std::max(worst, std::abs(got[i] - want[i]));
      mean += std::abs(got[i] - want[i]) / double(got.size());
    }
    // The loss above after each operator and the sRGB encoding: BY to 5 bits is up to a tenth of
    // the blue of a yellow (blue a seventh of the luminance), 3 code values here.
    EXPECT_LE(worst, 3) << op;
    EXPECT_LT(mean, 0.5) << op;
  }
}

}  // namespace cgtmo::pipeline
