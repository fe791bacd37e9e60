// src/cgtmo/io/scene_reader.cpp and exr_parts.cpp on bad and unusual input, written to a temporary
// folder by the test: generic channel names, a sidecar that is not JSON or lacks fields, a probe
// of the wrong size or projection, passes of mismatched size, unfamiliar names, a truncated file.
#include "cgtmo/io/scene_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "cgtmo/errors.h"
#include "support/error_of.h"
#include "support/exr_writer.h"

using namespace cgtmo;
using scene::Pass;
using test::PartSpec;

namespace {

// A 4x2 generic render: R,G,B; P.x..; N.x..; albedo.r..; Z; lightgroup.key / lightgroup.sky.
PartSpec generic_frame() {
  PartSpec p;
  p.width = 4;
  p.height = 2;
  p.names = {"R", "G", "B", "P.x", "P.y", "P.z", "N.x", "N.y", "N.z", "albedo.r", "albedo.g", "albedo.b", "Z",
             "lightgroup.key.R", "lightgroup.key.G", "lightgroup.key.B", "lightgroup.sky.R", "lightgroup.sky.G",
             "lightgroup.sky.B"};
  const std::size_t k = p.names.size();
  p.pixels.assign(8 * k, 0.0f);
  for (std::size_t i = 0; i < 8; ++i) {
    float* px = &p.pixels[i * k];
    px[0] = px[1] = px[2] = 0.5f + float(i);          // beauty
    px[3] = float(i), px[4] = 1.0f, px[5] = 2.0f;    // position
    px[6] = 0.0f, px[7] = 0.0f, px[8] = 0.3f;        // normal of length 0.3 (an averaged edge)
    px[9] = px[10] = px[11] = 0.5f;                  // albedo
    px[12] = 3.0f;                                   // depth
    px[13] = px[14] = px[15] = 0.5f + float(i);      // key carries everything; sky stays 0
  }
  float* bg = &p.pixels[7 * k];  // last pixel: background
  bg[3] = bg[4] = bg[5] = bg[6] = bg[7] = bg[8] = 0.0f;
  bg[12] = 1e10f;
  float* edge = &p.pixels[6 * k];  // a degenerate normal on geometry
  edge[6] = edge[7] = edge[8] = 0.0f;
  return p;
}

const char* kSidecar = R"({"camera": {"world_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
  "fov_x_rad": 0.8, "resolution": [4, 2]},
  "lights": [{"name": "key", "type": "POINT", "lightgroup": "key", "luminance": 12.5},
             {"name": "sky", "type": "WORLD", "lightgroup": "sky", "luminance": 0.5}],
  "probe": {"projection": "equirectangular", "resolution": [8, 4]}})";

PartSpec probe(int w, int h) {
  PartSpec p;
  p.width = w;
  p.height = h;
  p.names = {"R", "G", "B"};
  return p;
}

io::SceneRequest all_required() {
  io::SceneRequest r;
  r.required = scene::PassSet::all() - Pass::Emission;
  r.needed_by = "cgtmo";
  return r;
}

}  // namespace

TEST(SceneReaderInput, GenericNamesWithCompanionsByConvention) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  test::write_text(dir.file("shot.json"), kSidecar);
  test::write_exr(dir.file("shot.probe.exr"), {probe(8, 4)});
  const io::Scene s = io::read_scene(dir.file("shot.exr"), all_required());
  const scene::Frame& f = s.frame;
  EXPECT_EQ(s.channels.scheme, "generic");
  EXPECT_EQ(f.channels, 3);
  EXPECT_FLOAT_EQ(f.beauty[3 * 2], 2.5f);
  // Depth 1e10 -> background, only the last pixel.
  EXPECT_EQ(f.background, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 1}));
  // (0, 0, 0.3) renormalised to (0, 0, 1); the zero normals are invalid, one of them on geometry.
  EXPECT_FLOAT_EQ(f.normal[2], 1.0f);
  EXPECT_EQ(f.normal_valid, (std::vector<std::uint8_t>{1, 1, 1, 1, 1, 1, 0, 0}));
  EXPECT_EQ(s.invalid_normals, 1u);
  EXPECT_FLOAT_EQ(f.position[3 * 5], 5.0f);
  ASSERT_EQ(f.light_groups.size(), 2u);
  EXPECT_FALSE(f.light_groups[0].all_zero);
  EXPECT_TRUE(f.light_groups[1].all_zero);
  EXPECT_NE(std::find(s.warnings.begin(), s.warnings.end(), "light group 'sky' is zero in every pixel"), s.warnings.end());
  ASSERT_TRUE(s.sidecar && s.probe);
  EXPECT_EQ(s.probe->width, 8);
  EXPECT_DOUBLE_EQ(s.sidecar->light_for_group("key")->luminance, 12.5);
}

TEST(SceneReaderInput, CompanionsAreOptionalUnlessRequired) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  const io::Scene s = io::read_scene(dir.file("shot.exr"), all_required());
  EXPECT_FALSE(s.probe.has_value());
  EXPECT_FALSE(s.sidecar.has_value());
  EXPECT_EQ(s.probe_path, dir.file("shot.probe.exr"));
  io::SceneRequest r = all_required();
  r.probe = io::Companion::Require;
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), r); }).find("shot.probe.exr': no such file"),
            std::string::npos);
  r = all_required();
  r.sidecar_path = dir.file("elsewhere.json");  // an explicit path must exist
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), r); }).find("elsewhere.json': no such file"),
            std::string::npos);
}

TEST(SceneReaderInput, SidecarNotJsonOrIncomplete) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  test::write_text(dir.file("shot.json"), "{\"camera\": ");
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("not JSON"), std::string::npos);
  test::write_text(dir.file("shot.json"), R"({"camera": {"world_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
    "fov_x_rad": 0.8, "resolution": [4, 2]}, "lights": [{"name": "key", "type": "POINT", "lightgroup": "key"}]})");
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("lights[0] lacks 'luminance'"),
            std::string::npos);
}

TEST(SceneReaderInput, SidecarOfAnotherResolution) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  std::string side = kSidecar;
  side.replace(side.find("[4, 2]"), 6, "[8, 4]");
  test::write_text(dir.file("shot.json"), side);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("describes a 8x4 render"),
            std::string::npos);
}

TEST(SceneReaderInput, ProbeOfTheWrongSizeOrProjection) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  test::write_exr(dir.file("shot.probe.exr"), {probe(8, 8)});  // a square: not equirectangular
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("twice as wide as high"),
            std::string::npos);
  test::write_exr(dir.file("shot.probe.exr"), {probe(16, 8)});  // 2:1, but not what the sidecar says
  test::write_text(dir.file("shot.json"), kSidecar);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("is 16x8 but sidecar"),
            std::string::npos);
  std::string side = kSidecar;
  side.replace(side.find("equirectangular"), 15, "cubemap");
  test::write_text(dir.file("shot.json"), side);
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }).find("projection 'cubemap'"),
            std::string::npos);
}

TEST(SceneReaderInput, ProbeWithoutRgbIsNamedInTheError) {
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  PartSpec depth_only = probe(8, 4);
  depth_only.names = {"Z"};
  test::write_exr(dir.file("shot.probe.exr"), {depth_only});
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }),
            "'" + dir.file("shot.probe.exr") + "': no RGB layer found (layers: (top level))");
}

TEST(SceneReaderInput, CompanionsThatAreNotRegularFilesAreRefused) {
  // Found by convention, a FIFO or folder is not passed over as absent, nor read (a FIFO would block).
  test::TempDir dir;
  test::write_exr(dir.file("shot.exr"), {generic_frame()});
  ASSERT_EQ(::mkfifo(dir.file("shot.json").c_str(), 0600), 0);
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }),
            "sidecar '" + dir.file("shot.json") + "': not a regular file (FIFO)");
  std::filesystem::remove(dir.file("shot.json"));
  std::filesystem::create_directory(dir.file("shot.probe.exr"));
  EXPECT_EQ(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("shot.exr"), all_required()); }),
            "'" + dir.file("shot.probe.exr") + "': is a folder");
}

TEST(SceneReaderInput, PassesOfMismatchedSizeArePlacedByTheirDataWindow) {
  // A two-part EXR (as Nuke writes): the beauty at 4x2, the normals' data window 2x1 at (0,0).
  test::TempDir dir;
  PartSpec beauty = probe(4, 2);
  beauty.part_name = "rgba";
  PartSpec normals;
  normals.width = 2;
  normals.height = 1;
  normals.names = {"N.x", "N.y", "N.z"};
  normals.part_name = "normals";
  test::write_exr(dir.file("parts.exr"), {beauty, normals});
  io::SceneRequest r;
  r.required = Pass::Beauty | Pass::Normal;
  const io::Scene small = io::read_scene(dir.file("parts.exr"), r);
  ASSERT_EQ(small.frame.normal.size(), 24u);
  // Inside the part's window (pixels 0 and 1 of row 0) a normal; elsewhere none, marked invalid.
  for (int i = 0; i < 8; ++i) EXPECT_EQ(small.frame.normal_valid[std::size_t(i)], i < 2 ? 1 : 0) << i;
  EXPECT_EQ(small.invalid_normals, 6u);  // no depth pass: every pixel counts as foreground
  // Same sizes across parts read fine.
  normals.width = 4;
  normals.height = 2;
  test::write_exr(dir.file("parts.exr"), {beauty, normals});
  const io::Scene s = io::read_scene(dir.file("parts.exr"), r);
  EXPECT_EQ(s.frame.normal.size(), 24u);
}

TEST(SceneReaderInput, PassesAcrossPartsAndScanlineBlocksKeepTheirValues) {
  // Every pass is decoded in one pass over each part, 32 scanlines at a time (exr_parts.cpp): a
  // frame of 70 rows (a last partial block), two parts, and the position pass split between them.
  test::TempDir dir;
  const int w = 5, h = 70;
  const std::size_t npx = std::size_t(w) * h;
  auto value = [](int channel, std::size_t px) { return float(1000 * channel) + float(px); };  // exact in float
  PartSpec a, b;
  a.width = b.width = w;
  a.height = b.height = h;
  a.part_name = "rgba";
  a.names = {"R", "G", "B", "P.x", "P.y", "Z", "lightgroup.key.R", "lightgroup.key.G", "lightgroup.key.B"};
  b.part_name = "aovs";
  b.names = {"N.x", "N.y", "N.z", "albedo.r", "albedo.g", "albedo.b", "P.z"};
  for (PartSpec* part : {&a, &b}) {
    const std::size_t k = part->names.size();
    part->pixels.resize(npx * k);
    for (std::size_t px = 0; px < npx; ++px)
      for (std::size_t c = 0; c < k; ++c) part->pixels[px * k + c] = value(int(c) + (part == &b ? 100 : 0), px);
  }
  for (std::size_t px = 0; px < npx; ++px) {  // unit normals (the reader normalises them)
    b.pixels[px * 7 + 0] = 0.6f, b.pixels[px * 7 + 1] = 0.0f, b.pixels[px * 7 + 2] = 0.8f;
  }
  test::write_exr(dir.file("parts.exr"), {a, b});
  io::SceneRequest r;
  r.required = Pass::Beauty | Pass::Position | Pass::Normal | Pass::Albedo | Pass::Depth | Pass::LightGroups;
  const io::Scene s = io::read_scene(dir.file("parts.exr"), r);
  const scene::Frame& f = s.frame;
  ASSERT_EQ(f.width, w);
  ASSERT_EQ(f.height, h);
  ASSERT_EQ(f.beauty.size(), npx * 3);
  ASSERT_EQ(f.position.size(), npx * 3);
  ASSERT_EQ(f.albedo.size(), npx * 3);
  ASSERT_EQ(f.depth.size(), npx);
  ASSERT_EQ(f.normal.size(), npx * 3);
  ASSERT_EQ(f.light_groups.size(), 1u);
  for (std::size_t px = 0; px < npx; ++px) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(f.beauty[px * 3 + c], value(c, px)) << px;
      ASSERT_EQ(f.albedo[px * 3 + c], value(103 + c, px)) << px;
      ASSERT_EQ(f.light_groups[0].rgb[px * 3 + c], value(6 + c, px)) << px;
    }
    ASSERT_EQ(f.position[px * 3 + 0], value(3, px)) << px;
    ASSERT_EQ(f.position[px * 3 + 1], value(4, px)) << px;
    ASSERT_EQ(f.position[px * 3 + 2], value(106, px)) << px;  // from the other part
    ASSERT_EQ(f.depth[px], value(5, px)) << px;
    ASSERT_NEAR(f.normal[px * 3 + 0], 0.6f, 1e-6f) << px;
    ASSERT_NEAR(f.normal[px * 3 + 2], 0.8f, 1e-6f) << px;
  }
}

TEST(SceneReaderInput, UnfamiliarNames) {
  test::TempDir dir;
  PartSpec p;
  p.width = 4;
  p.height = 2;
  p.names = {"diffuse.u", "diffuse.v", "diffuse.w"};
  test::write_exr(dir.file("other.exr"), {p});
  EXPECT_NE(cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("other.exr"), all_required()); }).find("no RGB layer"),
            std::string::npos);
  // A beauty, but normals under a name no renderer we know uses: the pass, who needs it, what was tried.
  p.names = {"R", "G", "B", "nrm.u", "nrm.v", "nrm.w"};
  test::write_exr(dir.file("other.exr"), {p});
  io::SceneRequest r;
  r.required = Pass::Beauty | Pass::Normal;
  r.needed_by = "cgtmo (guide: normal)";
  const std::string e = cgtmo::test::error_of<DataError>([&] { io::read_scene(dir.file("other.exr"), r); });
  EXPECT_NE(e.find("no normal pass, needed by cgtmo (guide: normal)"), std::string::npos) << e;
  EXPECT_NE(e.find("N.X,Y,Z"), std::string::npos) << e;
  EXPECT_NE(e.find("nrm"), std::string::npos) << e;  // what the file has
}

TEST(SceneReaderInput, TruncatedFile) {
  test::TempDir dir;
  PartSpec big = generic_frame();
  big.width = 64;
  big.height = 64;
  big.pixels.clear();  // filled by the writer
  test::write_exr(dir.file("full.exr"), {big});
  const auto size = std::filesystem::file_size(dir.file("full.exr"));
  std::filesystem::copy_file(dir.file("full.exr"), dir.file("cut.exr"));
  std::filesystem::resize_file(dir.file("cut.exr"), size * 2 / 3);
  EXPECT_THROW(io::read_scene(dir.file("cut.exr"), all_required()), DataError);
  std::filesystem::resize_file(dir.file("cut.exr"), 20);  // not even a header
  EXPECT_THROW(io::read_scene(dir.file("cut.exr"), all_required()), DataError);
  EXPECT_THROW(io::read_scene(dir.file("missing.exr"), all_required()), DataError);
}

// Depth the reader cannot trust marks background, whatever the sign: -inf and NaN (a compositing
// division by zero) as well as +inf and Blender's 1e10, and 1e9 (a 24-bit codec's rounding of
// 1e10); a depth just under 1e9 is geometry. A non-finite normal has no direction.
TEST(SceneReaderInput, NonFiniteDepthIsBackgroundAndNonFiniteNormalHasNoDirection) {
  test::TempDir dir;
  PartSpec p = generic_frame();
  const std::size_t k = p.names.size();
  const float inf = std::numeric_limits<float>::infinity();
  const float depths[8] = {-inf, inf, std::nanf(""), 1e9f, 9.99e8f, 3.0f, 3.0f, 1e10f};
  for (std::size_t i = 0; i < 8; ++i) p.pixels[i * k + 12] = depths[i];
  p.pixels[5 * k + 7] = std::nanf("");  // pixel 5: normal (0, NaN, 0.3)
  test::write_exr(dir.file("r.exr"), {p});
  io::SceneRequest req = all_required();
  req.probe = req.sidecar = io::Companion::Skip;
  const io::Scene s = io::read_scene(dir.file("r.exr"), req);
  const std::vector<std::uint8_t> expected = {1, 1, 1, 1, 0, 0, 0, 1};
  EXPECT_EQ(s.frame.background, expected);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(scene::is_background(s.frame, i), expected[i] != 0) << "pixel " << i;
  EXPECT_EQ(s.frame.normal_valid[5], 0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(s.frame.normal[3 * 5 + c], 0.0f);
  EXPECT_EQ(s.frame.normal_valid[4], 1);  // length 0.3, renormalised
  EXPECT_NEAR(s.frame.normal[3 * 4 + 2], 1.0f, 1e-6f);
}
