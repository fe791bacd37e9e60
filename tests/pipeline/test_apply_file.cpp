// pipeline::Applier against results worked out by hand: Reinhard's x / (1 + x) after the
// exposure, the sRGB encoding of the built-in config, and requests refused before anything is
// read or written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/pipeline/apply_file.h"
#include "support/exr_writer.h"

namespace cgtmo::pipeline {
namespace {

namespace fs = std::filesystem;

// A 4x2 linear Rec.709 frame from black to far above white; no chromaticities attribute, so the
// built-in config's scene_linear role (linear Rec.709) is its colour space.
const std::vector<float> kPixels = {0.f,  0.f,  0.f,  0.01f, 0.02f, 0.03f, 0.18f, 0.18f, 0.18f, 0.5f, 1.f,  2.f,
                                    1.f,  1.f,  1.f,  4.f,   0.25f, 0.f,   16.f,  8.f,   32.f,  100.f, 50.f, 1000.f};

std::string write_input(const test::TempDir& dir) {
  const std::string path = dir.file("in.exr");
  test::PartSpec part;
  part.width = 4;
  part.height = 2;
  part.names = {"R", "G", "B"};
  part.pixels = kPixels;
  test::write_exr(path, {part});
  return path;
}

double reinhard(double x) { return x / (1 + x); }

// IEC 61966-2-1.
double srgb_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

ApplyOptions reinhard_options() {
  ::unsetenv("OCIO");  // the built-in config, whatever the environment says
  ApplyOptions o;
  o.op = "reinhard";
  return o;
}

TEST(ApplyFile, WritesTheOperatorsOutputAfterTheExposure) {
  test::TempDir dir;
  const std::string in = write_input(dir), out = dir.file("out.exr");
  ApplyOptions o = reinhard_options();
  o.encode_display = false;
  o.exposure_ev = 1.0;
  std::vector<std::string> stages;
  FileHooks hooks;
  hooks.on_stage = [&](const Stage& s) { stages.push_back(s.name); };
  const ApplyReport rep = Applier(o).apply_file(in, out, hooks);
  EXPECT_EQ(rep.width, 4);
  EXPECT_EQ(rep.height, 2);
  EXPECT_EQ(stages, (std::vector<std::string>{"read", "tone-map", "write"}));
  const scene::Frame got = io::read_beauty(out, "");
  ASSERT_EQ(got.beauty.size(), kPixels.size());
  for (std::size_t i = 0; i < kPixels.size(); ++i)
    EXPECT_NEAR(got.beauty[i], reinhard(2.0 * kPixels[i]), 1e-6) << "value " << i;
  // Nothing but the output is left in the folder (the temporary file was renamed).
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir.path)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"in.exr", "out.exr"}));
}

TEST(ApplyFile, PixelsAreEncodedForTheDefaultDisplay) {
  std::vector<float> px = kPixels;
  const ApplyReport rep = Applier(reinhard_options()).apply_pixels(px.data(), 4, 2, 3);
  EXPECT_EQ(rep.display, "sRGB");
  EXPECT_EQ(rep.view, "Standard");
  for (std::size_t i = 0; i < px.size(); ++i) EXPECT_NEAR(px[i], srgb_encode(reinhard(kPixels[i])), 2e-4) << "value " << i;
}

TEST(ApplyFile, BadRequestsReadAndWriteNothing) {
  test::TempDir dir;
  const std::string in = write_input(dir);
  ApplyOptions o = reinhard_options();
  o.op = "reinhardt";
  EXPECT_THROW(Applier{o}, UsageError);
  o = reinhard_options();
  o.params = {{"no_such_parameter", "1"}};
  EXPECT_THROW(Applier{o}, UsageError);
  o = reinhard_options();
  o.exposure_ev = 65;
  EXPECT_THROW(Applier{o}, UsageError);

  const Applier applier(reinhard_options());
  // The output is checked before the input is read: a missing input is not what is reported.
  const std::string nowhere = dir.file("no/such/folder/out.png");
  try {
    applier.apply_file(dir.file("missing.exr"), nowhere);
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
  }
  EXPECT_THROW(applier.apply_file(dir.file("missing.exr"), dir.file("out.png")), std::exception);
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
  EXPECT_THROW(applier.apply_file(in, in), std::exception);  // never over its own input
  std::vector<float> px(6, 1.f);
  EXPECT_THROW(applier.apply_pixels(px.data(), 2, 1, 2), DataError);  // two channels
}

// The alpha rule (docs/exr-inputs.md): an alpha that covers no pixel while the colour is not black
// is dropped with a warning (OpenEXR's Carrots.exr, alpha 0 everywhere, came out as a wholly
// transparent PNG); any coverage, or nothing to show, leaves the alpha as it is.
TEST(ApplyFile, AnAlphaCoveringNothingIsDroppedWithAWarning) {
  test::TempDir dir;
  auto rgba = [&](const std::string& name, float colour, float alpha_at_0) {
    test::PartSpec part;
    part.width = 4;
    part.height = 2;
    part.names = {"R", "G", "B", "A"};
    for (int i = 0; i < 8; ++i) part.pixels.insert(part.pixels.end(), {colour, colour * 0.5f, colour * 0.25f, i == 0 ? alpha_at_0 : 0.f});
    test::write_exr(dir.file(name), {part});
    return dir.file(name);
  };
  auto channels_of = [](const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    return in ? in->spec().nchannels : -1;
  };
  struct Case {
    std::string in;
    int channels;
    bool warned;
  };
  for (const Case& c : {Case{rgba("empty-alpha.exr", 0.4f, 0.f), 3, true}, Case{rgba("one-covered.exr", 0.4f, 1.f), 4, false},
                        Case{rgba("black.exr", 0.f, 0.f), 4, false}, Case{rgba("nan-alpha.exr", 2.f, NAN), 3, true}}) {
    std::vector<std::string> warnings;
    ApplyOptions o = reinhard_options();
    o.warn = [&](const std::string& w) { warnings.push_back(w); };
    const std::string out = c.in + ".png";
    const ApplyReport rep = Applier(o).apply_file(c.in, out);
    EXPECT_EQ(rep.channels, c.channels) << c.in;
    EXPECT_EQ(channels_of(out), c.channels) << c.in;
    const std::string rule = "alpha is 0 at every pixel while the colour is not: alpha dropped, the output is opaque";
    EXPECT_EQ(std::count(warnings.begin(), warnings.end(), rule), c.warned ? 1 : 0) << c.in;
    EXPECT_EQ(rep.alpha.empty(), !c.warned) << c.in;
  }
}

}  // namespace
}  // namespace cgtmo::pipeline
