// src/cgtmo/io/chromaticities.cpp: the OpenEXR chromaticities attribute as written by OIIO (the
// way other tools write it), absent, and degenerate.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include "cgtmo/errors.h"
#include "cgtmo/io/chromaticities.h"
#include "support/exr_writer.h"

namespace cgtmo::io {
namespace {

void write_rgb(const std::string& path, const float* chromaticities) {
  OIIO::ImageSpec spec(4, 2, 3, OIIO::TypeDesc::FLOAT);
  if (chromaticities) spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chromaticities);
  const std::vector<float> px(4 * 2 * 3, 0.5f);
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close());
}

TEST(ReadChromaticities, AttributeAsWritten) {
  test::TempDir dir;
  const float ap1[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
  write_rgb(dir.file("ap1.exr"), ap1);
  const auto c = read_chromaticities(dir.file("ap1.exr"));
  ASSERT_TRUE(c);
  EXPECT_TRUE(color::same_chromaticities(*c, color::aces_ap1(), 1e-6));
}

TEST(ReadChromaticities, AbsentIsNone) {
  test::TempDir dir;
  write_rgb(dir.file("plain.exr"), nullptr);
  EXPECT_FALSE(read_chromaticities(dir.file("plain.exr")));
}

TEST(ReadChromaticities, DegenerateIsADataErrorNamingTheFile) {
  test::TempDir dir;
  const float zeros[8] = {};
  write_rgb(dir.file("zeros.exr"), zeros);
  try {
    read_chromaticities(dir.file("zeros.exr"));
    FAIL() << "accepted an all-zero attribute";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("zeros.exr"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_chromaticities(dir.file("missing.exr")), DataError);
}

}  // namespace
}  // namespace cgtmo::io
