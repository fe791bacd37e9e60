// src/cgtmo/io/input_file.cpp: what is refused before a reader opens a file (not a regular file,
// deep, more pixels than the memory budget or than the file's bytes could hold), and that valid
// files of every OpenEXR compression, at their most compressible, are not.
#include "cgtmo/io/input_file.h"

#include <OpenImageIO/deepdata.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "support/error_of.h"
#include "support/exr_writer.h"

using namespace cgtmo;

namespace {

// A constant image (the most compressible content) of `channels` halves.
void write_constant(const std::string& path, int w, int h, const std::string& compression, bool tiled, int channels = 3) {
  OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::HALF);
  spec.attribute("compression", compression);
  if (tiled) spec.tile_width = spec.tile_height = 32;
  std::vector<float> px(std::size_t(w) * h * channels, 0.5f);
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
  out->close();
}

std::vector<char> bytes_of(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& b) {
  std::ofstream f(path, std::ios::binary);
  f.write(b.data(), std::streamsize(b.size()));
}

// Where attribute `name` of type `type` keeps its int32 size (its value follows).
std::size_t attribute_size_at(const std::vector<char>& b, const std::string& name, const std::string& type) {
  const std::string key = name + '\0' + type + '\0';
  const auto it = std::search(b.begin(), b.end(), key.begin(), key.end());
  EXPECT_NE(it, b.end()) << name;
  return std::size_t(it - b.begin()) + key.size();
}

void put_i32(std::vector<char>& b, std::size_t at, std::int32_t v) { std::memcpy(&b[at], &v, 4); }  // little endian here

struct BudgetReset {
  ~BudgetReset() { io::set_memory_budget(0); }
};

}  // namespace

TEST(InputFile, OnlyRegularFilesAreInputs) {
  test::TempDir dir;
  test::write_text(dir.file("a.json"), "{}");
  EXPECT_EQ(io::input_file_problem(dir.file("a.json")), "");
  EXPECT_EQ(io::input_file_problem(dir.file("missing.exr")), "no such file");
  EXPECT_EQ(io::input_file_problem(dir.path.string()), "is a folder");
  EXPECT_EQ(io::input_file_problem("/dev/zero"), "not a regular file (character device)");
  ASSERT_EQ(::mkfifo(dir.file("fifo.exr").c_str(), 0600), 0);
  EXPECT_EQ(io::input_file_problem(dir.file("fifo.exr")), "not a regular file (FIFO)");
  std::filesystem::create_symlink("/dev/zero", dir.file("zero.exr"));  // links are followed
  EXPECT_EQ(io::input_file_problem(dir.file("zero.exr")), "not a regular file (character device)");
  std::filesystem::create_symlink(dir.file("a.json"), dir.file("b.json"));
  EXPECT_EQ(io::input_file_problem(dir.file("b.json")), "");
  // The readers refuse them before opening (a FIFO without a writer would block here forever).
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("fifo.exr")); }), "'" + dir.file("fifo.exr") + "': not a regular file (FIFO)");
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_header("/dev/zero"); }), "'/dev/zero': not a regular file (character device)");
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::require_input_file(dir.file("fifo.exr"), "sidecar "); }),
            "sidecar '" + dir.file("fifo.exr") + "': not a regular file (FIFO)");
}

TEST(InputFile, EveryCompressionAtItsMostCompressibleIsAccepted) {
  test::TempDir dir;
  const char* names[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
  for (int code = 0; code < 10; ++code)
    for (bool tiled : {false, true}) {
      const std::string path = dir.file(std::string(names[code]) + (tiled ? "_tiled" : "") + ".exr");
      write_constant(path, 512, 256, names[code], tiled);
      io::ExrDeclaration d;
      ASSERT_TRUE(io::read_exr_declaration(path, &d)) << path;
      ASSERT_EQ(d.parts.size(), 1u);
      const io::ExrPartDeclaration& p = d.parts[0];
      EXPECT_TRUE(p.valid_window);
      EXPECT_EQ(p.width, 512);
      EXPECT_EQ(p.height, 256);
      EXPECT_EQ(p.channels, 3);
      EXPECT_EQ(p.compression, code);
      EXPECT_EQ(p.tiled, tiled);
      EXPECT_DOUBLE_EQ(p.raw_bytes, 512.0 * 256 * 3 * 2);
      EXPECT_LE(double(d.header_bytes) + io::min_stored_bytes(p), double(std::filesystem::file_size(path))) << path;
      EXPECT_NO_THROW(io::read_header(path)) << path;
    }
}

TEST(InputFile, MultiPartFilesDeclareEveryPart) {
  test::TempDir dir;
  test::PartSpec a{8, 4, {"R", "G", "B"}, {}, "beauty"};
  test::PartSpec b{8, 4, {"Z"}, {}, "depth"};
  test::write_exr(dir.file("two.exr"), {a, b});
  io::ExrDeclaration d;
  ASSERT_TRUE(io::read_exr_declaration(dir.file("two.exr"), &d));
  ASSERT_EQ(d.parts.size(), 2u);
  EXPECT_EQ(d.parts[0].channels, 3);
  EXPECT_EQ(d.parts[1].channels, 1);
  EXPECT_EQ(d.parts[1].width, 8);
  EXPECT_DOUBLE_EQ(d.parts[1].raw_bytes, 8 * 4 * 4.0);  // float32
  test::write_text(dir.file("text.exr"), "not an EXR");
  EXPECT_FALSE(io::read_exr_declaration(dir.file("text.exr"), &d));  // left to OpenImageIO
}

TEST(InputFile, AHeaderDeclaringMoreThanTheFileHoldsIsRefusedBeforeOpening) {
  test::TempDir dir;
  write_constant(dir.file("small.exr"), 1000, 54, "zip", false);
  std::vector<char> b = bytes_of(dir.file("small.exr"));
  const std::size_t window = attribute_size_at(b, "dataWindow", "box2i") + 4;
  put_i32(b, window + 8, 7700000);  // xMax: 7,700,001 x 54, 5 GB as float32, in about 1 KB
  write_bytes(dir.file("wide.exr"), b);
  const std::string e = cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("wide.exr")); });
  EXPECT_NE(e.find("wide.exr': the header declares 7700001x54 pixels, 3 channels (zip, at most 1032:1)"), std::string::npos) << e;
  EXPECT_NE(e.find("(corrupt or truncated)"), std::string::npos) << e;
  // An attribute OpenEXR finds missing takes its default (ZIP here), so the check still applies
  // (found by fuzzing: without 'compression' the 7,700,001-pixel-wide window reached OpenEXR).
  std::vector<char> renamed = b;
  const std::string key = std::string("compression") + '\0' + "compression";
  std::copy_n("compressmon", 11, std::search(renamed.begin(), renamed.end(), key.begin(), key.end()));
  write_bytes(dir.file("renamed.exr"), renamed);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("renamed.exr")); }).find("7700001x54 pixels, 3 channels (zip"), std::string::npos);
  // A negative origin counts the same pixels (and no int32 overflows).
  put_i32(b, window, -2000000000);
  put_i32(b, window + 8, 2000000000);
  write_bytes(dir.file("negative.exr"), b);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("negative.exr")); }).find("declares 4000000001x54 pixels"), std::string::npos);

  // An attribute claiming more bytes than the file has: OpenEXR would allocate them.
  std::vector<char> c = bytes_of(dir.file("small.exr"));
  put_i32(c, attribute_size_at(c, "channels", "chlist"), 0x7fffffff);
  write_bytes(dir.file("attribute.exr"), c);
  const std::string a = cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("attribute.exr")); });
  EXPECT_NE(a.find("corrupt OpenEXR header (attribute 'channels' declares 2147483647 bytes"), std::string::npos) << a;
}

TEST(InputFile, AttributeSizesMustBeWhatOpenExrConsumes) {
  // OpenEXR reads a typed value by its type, not by its declared size, and then goes on from
  // there: found by fuzzing, a channel list declaring fewer bytes than it holds shifted OpenEXR
  // into reading channel entries as attributes, one of which declared 842 MB (allocated at once).
  test::TempDir dir;
  write_constant(dir.file("r.exr"), 8, 4, "zip", false);
  std::vector<char> b = bytes_of(dir.file("r.exr"));
  const std::size_t channels = attribute_size_at(b, "channels", "chlist");
  std::int32_t declared;
  std::memcpy(&declared, &b[channels], 4);
  put_i32(b, channels, declared + 18);  // the list ends one entry before its declared size
  write_bytes(dir.file("shifted.exr"), b);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("shifted.exr")); }).find("the channel list ends before its declared size"),
            std::string::npos);
  put_i32(b, channels, declared - 18);  // one channel entry beyond the declared size
  write_bytes(dir.file("shifted.exr"), b);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("shifted.exr")); }).find("the channel list has no end"), std::string::npos);
  // Tiles far larger than the image: OpenEXR allocates tile buffers by the declared tile size.
  {
    BudgetReset reset;
    io::set_memory_budget(64 << 20);
    write_constant(dir.file("t.exr"), 16, 8, "zip", true);
    b = bytes_of(dir.file("t.exr"));
    put_i32(b, attribute_size_at(b, "tiles", "tiledesc") + 4 + 4, 16777480);  // ySize
    write_bytes(dir.file("tall_tiles.exr"), b);
    EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("tall_tiles.exr")); }).find("more than the memory budget"), std::string::npos);
    EXPECT_NO_THROW(io::read_header(dir.file("t.exr")));
  }
  // A pixel type OpenEXR passes on and OpenImageIO aborts on (found by fuzzing).
  b = bytes_of(dir.file("r.exr"));
  put_i32(b, channels + 4 + 2, 3);  // the first entry: "B\0", then its int32 pixel type
  write_bytes(dir.file("type.exr"), b);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("type.exr")); }).find("channel 'B' has the unknown pixel type 3"),
            std::string::npos);
  b = bytes_of(dir.file("r.exr"));
  put_i32(b, attribute_size_at(b, "dataWindow", "box2i"), 17);
  write_bytes(dir.file("window.exr"), b);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("window.exr")); }).find("attribute 'dataWindow' of type box2i declares 17 bytes instead of 16"),
            std::string::npos);
}

TEST(InputFile, AnImageAboveTheMemoryBudgetIsRefused) {
  BudgetReset reset;
  test::TempDir dir;
  // 24 KB as float32, 48 KB to read: OpenImageIO converts at least 64 rows at a time.
  write_constant(dir.file("r.exr"), 64, 32, "zip", false);
  EXPECT_GT(io::default_memory_budget(), 0u);
  EXPECT_EQ(io::memory_budget(), io::default_memory_budget());
  io::set_memory_budget(40 * 1024);
  const std::string e = cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("r.exr")); });
  EXPECT_NE(e.find("r.exr': 64x32 pixels, 3 channels need 48.0 KB to read as float32, more than the memory budget"), std::string::npos) << e;
  io::set_memory_budget(48 * 1024);
  EXPECT_NO_THROW(io::read_header(dir.file("r.exr")));
  // Other formats are checked from their OpenImageIO spec.
  OIIO::ImageSpec spec(64, 32, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> px(64 * 32 * 3, 128);
  auto out = OIIO::ImageOutput::create(dir.file("r.png"));
  ASSERT_TRUE(out->open(dir.file("r.png"), spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  out->close();
  io::set_memory_budget(40 * 1024);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("r.png")); }).find("more than the memory budget"), std::string::npos);
}

TEST(InputFile, DeepImagesAreRefusedByName) {
  test::TempDir dir;
  OIIO::ImageSpec spec(4, 2, 5, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A", "Z"};
  spec.deep = true;
  OIIO::DeepData deep;
  deep.init(spec);
  for (int px = 0; px < 8; ++px) {
    deep.set_samples(px, 1);
    for (int c = 0; c < 5; ++c) deep.set_deep_value(px, c, 0, 0.5f);
  }
  auto out = OIIO::ImageOutput::create(dir.file("deep.exr"));
  ASSERT_TRUE(out->open(dir.file("deep.exr"), spec)) << out->geterror();
  ASSERT_TRUE(out->write_deep_image(deep)) << out->geterror();
  out->close();
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("deep.exr")); }), "'" + dir.file("deep.exr") + "': deep images are not supported");
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_beauty(dir.file("deep.exr"), ""); }), "'" + dir.file("deep.exr") + "': deep images are not supported");
}

TEST(InputFile, TheFormatIsChosenByContentOrExtensionNeverByProbing) {
  // OpenImageIO, asked to open a file, tries every format it knows when the extension's fails;
  // some decode the whole image in open() (fuzzing found a 563-byte file that, taken for WebP,
  // made it allocate 12035x3188x4 bytes) before any declared size could be checked.
  test::TempDir dir;
  OIIO::ImageSpec spec(8, 4, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> px(8 * 4 * 3, 128);
  auto out = OIIO::ImageOutput::create(dir.file("p.png"));
  ASSERT_TRUE(out->open(dir.file("p.png"), spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()));
  out->close();
  EXPECT_EQ(io::read_header(dir.file("p.png")).format, "png");
  std::filesystem::copy_file(dir.file("p.png"), dir.file("png_named.exr"));
  const std::string e = cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("png_named.exr")); });
  EXPECT_NE(e.find("is not an OpenEXR file"), std::string::npos) << e;
  std::filesystem::copy_file(dir.file("p.png"), dir.file("png_without_extension"));
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_header(dir.file("png_without_extension")); }).find("no extension names another format"),
            std::string::npos);
  write_constant(dir.file("r.exr"), 8, 4, "zip", false);  // OpenEXR is known by its magic number
  std::filesystem::copy_file(dir.file("r.exr"), dir.file("r.tmp"));
  EXPECT_EQ(io::read_header(dir.file("r.tmp")).format, "openexr");
}
