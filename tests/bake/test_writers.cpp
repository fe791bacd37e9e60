// Checks src/cgtmo/bake/writers.cpp: the 3D .cube export (Resolve layout, a 1D section then a 3D
// LUT) as OpenColorIO reads it, against Reinhard-Jodie and the sRGB encoding written out here;
// and the staged outputs (StagedFiles): renamed together, leftovers of killed bakes removed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cgtmo/bake/choose.h"
#include "cgtmo/bake/lut.h"
#include "cgtmo/bake/writers.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;
using namespace cgtmo::bake;

namespace {

// Reinhard-Jodie (seed guide, double), unclamped: lerp(C / (1 + L), C / (1 + C), C / (1 + C)).
double jodie(const double in[3], int c) {
  const double L = 0.2126 * in[0] + 0.7152 * in[1] + 0.0722 * in[2];
  const double lum = in[c] / (1 + L), tv = in[c] / (1 + in[c]);
  return lum + (tv - lum) * tv;
}

// IEC 61966-2-1 encoding, its linear segment continued below 0 and its power law above 1.
double srgb_extended(double y) { return y <= 0.0031308 ? 12.92 * y : 1.055 * std::pow(y, 1 / 2.4) - 0.055; }

struct CubeFixture {
  BakeSubject s = make_subject(operators::find_operator("reinhard-jodie"), {}, reference_scene_stats());
  Representation r;
  BakedLut lut;
  std::string text, path;
  OCIO::ConstCPUProcessorRcPtr cpu;
  explicit CubeFixture(bool warped) {
    r.dims = 3;
    r.warped = warped;
    r.size = 9;
    r.shaper = {-8, 16};
    r.out_log2 = -8;
    lut = sample_lut(*s.unclamped, r);
    text = cube_3d_text(r, lut.warp, *s.unclamped, "test");
    path = ::testing::TempDir() + (warped ? "cgtmo_test_w.cube" : "cgtmo_test_u.cube");
    std::ofstream(path) << text;
    auto g = OCIO::GroupTransform::Create();
    g->appendTransform(kShaperSpace.transform());
    auto f = OCIO::FileTransform::Create();
    f->setSrc(path.c_str());
    f->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    g->appendTransform(f);
    cpu = OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultCPUProcessor();
  }
  ~CubeFixture() { std::remove(path.c_str()); }
  // Node j of channel c, as a linear input: where the pre-curve (or the shaper alone) reaches
  // j / 8, found by bisection.
  double node_input(int c, int j) const {
    double a = 0, b = 1;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      double w = m;
      if (r.warped) {
        const double x = m * (r.warp_size - 1);
        const int i = std::min(int(x), r.warp_size - 2);
        w = lut.warp[std::size_t(i) * 3 + c] + (x - i) * (lut.warp[std::size_t(i + 1) * 3 + c] - lut.warp[std::size_t(i) * 3 + c]);
      }
      (w < j / 8.0 ? a : b) = m;
    }
    return r.shaper.inverse(0.5 * (a + b));
  }
};

}  // namespace

TEST(CubeExport, HeaderHasBothSectionsInResolveLayout) {
  CubeFixture fx(true);
  std::istringstream in(fx.text);
  std::string line;
  std::vector<std::string> keys;
  int numeric = 0;
  while (std::getline(in, line)) {
    if (line.rfind("LUT_", 0) == 0) keys.push_back(line);
    else if (!line.empty() && line[0] != '#') ++numeric;
  }
  const std::vector<std::string> want{"LUT_1D_SIZE 4096", "LUT_1D_INPUT_RANGE 0.0 1.0", "LUT_3D_SIZE 9", "LUT_3D_INPUT_RANGE 0.0 1.0"};
  EXPECT_EQ(keys, want);
  EXPECT_EQ(numeric, 4096 + 9 * 9 * 9);
}

// OCIO 2.1 must apply the 1D section (Log2 Shaper -> grid coordinate) and then the 3D LUT: at the
// 3D grid's nodes the read-back value is the operator's, sRGB-encoded and unclamped. Skipping
// the 1D section or applying it after the 3D LUT would put these inputs far from the nodes.
TEST(CubeExport, OcioAppliesTheOneDSectionThenTheThreeDLut) {
  for (bool warped : {false, true}) {
    CubeFixture fx(warped);
    const int nodes[][3] = {{0, 0, 0}, {3, 5, 1}, {8, 0, 2}, {1, 8, 7}, {4, 4, 4}, {2, 6, 0}, {7, 7, 8}, {8, 8, 8}};
    for (const auto& n : nodes) {
      const double in[3] = {fx.node_input(0, n[0]), fx.node_input(1, n[1]), fx.node_input(2, n[2])};
      float rgb[3] = {float(in[0]), float(in[1]), float(in[2])};
      fx.cpu->applyRGB(rgb);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rgb[c], srgb_extended(jodie(in, c)), 2e-3)
            << (warped ? "warped " : "uniform ") << n[0] << "," << n[1] << "," << n[2] << " channel " << c;
    }
  }
}

namespace {

namespace fs = std::filesystem;

struct StagingDir {
  fs::path path = fs::temp_directory_path() / ("cgtmo_staged_" + std::to_string(::getpid()));
  StagingDir() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~StagingDir() { fs::remove_all(path); }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& e : fs::directory_iterator(path)) n.push_back(e.path().filename().string());
    std::sort(n.begin(), n.end());
    return n;
  }
};

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(StagedFiles, CommitRenamesEveryFileAndLeavesNoStagingFolder) {
  const StagingDir dir;
  StagedFiles staged;
  staged.stage((dir.path / "a.spi1d").string(), "lut");
  staged.stage((dir.path / "a.ocio").string(), "config");
  EXPECT_EQ(dir.names().size(), 1u);  // the staging folder only
  EXPECT_EQ(staged.staging_folder(dir.path.string() + "/"), staged.staging_folder(dir.path.string()));
  staged.commit();
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"a.ocio", "a.spi1d"}));
  EXPECT_EQ(read_text(dir.path / "a.ocio"), "config");
}

TEST(StagedFiles, UncommittedFilesLeaveNothing) {
  const StagingDir dir;
  {
    StagedFiles staged;
    staged.stage((dir.path / "a.spi1d").string(), "lut");
  }
  EXPECT_TRUE(dir.names().empty());
}

// A bake killed before its commit leaves its staging folder (unlocked once it is dead): the next
// bake staging into that folder removes it and says so.
TEST(StagedFiles, KilledBakesStagingFolderIsRemovedByTheNextOne) {
  const StagingDir dir;
  io::StagingFolder killed = io::create_staging_folder(dir.path.string());
  std::ofstream(fs::path(killed.path) / "a.spi1d") << "partial";
  const std::string killed_path = killed.path;
  io::release_staging_folder(killed, false);
  std::string note;
  StagedFiles staged([&](const std::string& s) { note += s; });
  staged.stage((dir.path / "a.spi1d").string(), "lut");
  EXPECT_FALSE(fs::exists(killed_path));
  EXPECT_EQ(note, "removed 1 staging folder left by an interrupted run in '" + dir.path.string() + "'");
  staged.commit();
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"a.spi1d"}));
}

// Failing to write or rename is an I/O failure (exit 1), not a usage error (exit 2).
TEST(StagedFiles, RenameFailureIsADataError) {
  const StagingDir dir;
  fs::create_directories(dir.path / "a.ocio" / "in-the-way");
  StagedFiles staged;
  staged.stage((dir.path / "a.ocio").string(), "config");
  EXPECT_THROW(staged.commit(), DataError);
}
