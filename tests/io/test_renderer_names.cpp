// The beauty as other renderers and compositors name it (src/cgtmo/scene/passes.cpp,
// io::find_beauty; docs/exr-inputs.md): Nuke's rgba layer with red/green/blue/alpha, Arnold's
// beauty AOV RGBA, RenderMan's Ci and its lower-case r, g, b, a. Each layer of a test file holds a
// value of its own, so a test sees which one was read; an RGB layer under another name (an AOV
// such as diffuse) is never taken for the beauty unasked.
#include <gtest/gtest.h>

#include <utility>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "support/error_of.h"
#include "support/exr_writer.h"

using namespace cgtmo;

namespace {

// A 4x2 file: each channel holds the value given with its name at every pixel.
void write_channels(const std::string& path, const std::vector<std::pair<std::string, float>>& channels) {
  test::PartSpec p;
  p.width = 4;
  p.height = 2;
  for (const auto& [name, v] : channels) p.names.push_back(name);
  for (int i = 0; i < p.width * p.height; ++i)
    for (const auto& [name, v] : channels) p.pixels.push_back(v);
  test::write_exr(path, {p});
}

std::vector<std::pair<std::string, float>> layer(const std::string& prefix, std::vector<std::string> comps, float v) {
  std::vector<std::pair<std::string, float>> out;
  for (const auto& c : comps) out.emplace_back(prefix.empty() ? c : prefix + "." + c, c == comps.back() && comps.size() == 4 ? 0.5f : v);
  return out;
}

std::vector<std::pair<std::string, float>> operator+(std::vector<std::pair<std::string, float>> a,
                                                     const std::vector<std::pair<std::string, float>>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

struct Read {
  std::string layer;
  int channels = 0;
  float red = 0, alpha = -1;
};

Read read(const std::string& path, const std::string& layer = "") {
  const scene::Frame f = io::read_beauty(path, layer);
  return {f.layer, f.channels, f.beauty[0], f.channels == 4 ? f.beauty[3] : -1.f};
}

}  // namespace

// Nuke's main layer is rgba (channels rgba.red, rgba.green, rgba.blue, rgba.alpha); a file with
// an albedo layer spelled diffuse.R used to be tone-mapped as if diffuse were the beauty.
TEST(RendererNames, NukeRgbaLayerIsTheBeautyAndLayerNamesIt) {
  test::TempDir dir;
  const std::string path = dir.file("nuke.exr");
  write_channels(path, layer("diffuse", {"R", "G", "B"}, 0.2f) + layer("rgba", {"red", "green", "blue", "alpha"}, 3.0f) +
                           layer("depth", {"Z"}, 7.0f));
  const Read automatic = read(path);
  EXPECT_EQ(automatic.layer, "rgba");
  EXPECT_EQ(automatic.channels, 4);
  EXPECT_EQ(automatic.red, 3.0f);
  EXPECT_EQ(automatic.alpha, 0.5f);
  EXPECT_EQ(read(path, "rgba").red, 3.0f);
  EXPECT_EQ(read(path, "diffuse").red, 0.2f);  // still there when asked for
  // The G-buffer beside it: Nuke's depth.Z.
  io::SceneRequest r;
  r.optional = scene::Pass::Depth;
  r.probe = r.sidecar = io::Companion::Skip;
  EXPECT_EQ(io::read_scene(path, r).frame.depth[0], 7.0f);
}

// Arnold's beauty AOV is RGBA: as the top-level R, G, B, A (then --layer RGBA means them) or as a
// layer of that name; its other AOVs (diffuse, specular, albedo) are never the beauty.
TEST(RendererNames, ArnoldRgbaAovTopLevelOrLayered) {
  test::TempDir dir;
  const std::string top = dir.file("arnold.exr");
  write_channels(top, layer("", {"R", "G", "B", "A"}, 4.0f) + layer("diffuse", {"R", "G", "B"}, 0.2f) +
                          layer("specular", {"R", "G", "B"}, 0.1f) + layer("albedo", {"R", "G", "B"}, 0.6f));
  EXPECT_EQ(read(top).layer, "");
  EXPECT_EQ(read(top).red, 4.0f);
  const Read named = read(top, "RGBA");
  EXPECT_EQ(named.layer, "");
  EXPECT_EQ(named.red, 4.0f);
  EXPECT_EQ(named.alpha, 0.5f);

  const std::string layered = dir.file("arnold-layered.exr");
  write_channels(layered, layer("N", {"R", "G", "B"}, 0.3f) + layer("RGBA", {"R", "G", "B", "A"}, 5.0f) +
                              layer("diffuse", {"R", "G", "B"}, 0.2f));
  EXPECT_EQ(read(layered).layer, "RGBA");
  EXPECT_EQ(read(layered).red, 5.0f);
  EXPECT_EQ(read(layered, "RGBA").red, 5.0f);
}

// RenderMan's beauty is Ci (Ci.r, Ci.g, Ci.b), or the top-level lower-case r, g, b, a.
TEST(RendererNames, RenderManCiAndLowerCaseRgba) {
  test::TempDir dir;
  const std::string ci = dir.file("ci.exr");
  write_channels(ci, layer("Ci", {"r", "g", "b"}, 6.0f) + layer("albedo", {"r", "g", "b"}, 0.6f) + layer("", {"z"}, 9.0f));
  EXPECT_EQ(read(ci).layer, "Ci");
  EXPECT_EQ(read(ci).channels, 3);
  EXPECT_EQ(read(ci).red, 6.0f);
  EXPECT_EQ(read(ci, "Ci").red, 6.0f);

  const std::string lower = dir.file("rgba-lower.exr");
  write_channels(lower, layer("", {"r", "g", "b", "a"}, 8.0f) + layer("albedo", {"r", "g", "b"}, 0.6f));
  const Read r = read(lower);
  EXPECT_EQ(r.layer, "");
  EXPECT_EQ(r.channels, 4);
  EXPECT_EQ(r.red, 8.0f);
  EXPECT_EQ(r.alpha, 0.5f);
  EXPECT_EQ(read(lower, "Ci").red, 8.0f);
}

// RGB layers under other names only: refused in one line that lists them and names --layer,
// which then reads the one asked for.
TEST(RendererNames, AnAovIsNeverTakenForTheBeautyUnasked) {
  test::TempDir dir;
  const std::string path = dir.file("aovs.exr");
  write_channels(path, layer("diffuse", {"R", "G", "B"}, 0.2f) + layer("specular", {"R", "G", "B"}, 0.1f) + layer("", {"Z"}, 3.0f));
  const std::string e = test::error_of<DataError>([&] { io::read_beauty(path, ""); });
  EXPECT_EQ(e, "'" + path + "': no layer is the beauty by name (R,G,B; <ViewLayer>.Combined; rgba; Ci; beauty): name it with "
                            "--layer (RGB layers: diffuse, specular; layers: (top level), diffuse, specular)");
  EXPECT_EQ(read(path, "specular").red, 0.1f);
  // A name the file lacks lists what it has.
  EXPECT_EQ(test::error_of<DataError>([&] { io::read_beauty(path, "rgba"); }),
            "'" + path + "': no RGB layer 'rgba' (layers: (top level), diffuse, specular)");
}
