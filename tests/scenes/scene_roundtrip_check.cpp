// Reads the tiny renders of render_roundtrip.sh back with the scene reader and checks that every
// pass, light group, the probe and the sidecar arrived and agree with one another.
// Usage: scene_roundtrip_check DIR NAME:WxH...   Exit 0 when all pass, 1 otherwise.
#include <cmath>
#include <cstdio>
#include <string>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/scene_reader.h"

using namespace cgtmo;

static int check(const std::string& dir, const std::string& spec) {
  const auto colon = spec.find(':'), x = spec.find('x', colon);  // after the colon: names may hold an x
  const std::string name = spec.substr(0, colon);
  const int w = std::stoi(spec.substr(colon + 1, x - colon - 1)), h = std::stoi(spec.substr(x + 1));
  io::SceneRequest req;
  req.required = scene::PassSet::all();
  req.needed_by = "the round-trip test";
  req.probe = io::Companion::Require;
  req.sidecar = io::Companion::Require;
  req.probe_passes = scene::Pass::LightGroups;
  int bad = 0;
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok) {
      std::printf("FAIL %s: %s\n", name.c_str(), what.c_str());
      ++bad;
    }
  };
  try {
    const io::Scene s = io::read_scene(dir + "/" + name + ".exr", req);
    const scene::Frame& f = s.frame;
    expect(f.width == w && f.height == h, "frame is " + std::to_string(f.width) + "x" + std::to_string(f.height));
    expect(s.channels.scheme == "blender", "channel names not recognised as Blender's");
    const std::size_t n = f.pixel_count();
    expect(f.position.size() == 3 * n && f.normal.size() == 3 * n && f.albedo.size() == 3 * n &&
               f.depth.size() == n && f.emission.size() == 3 * n,
           "a G-buffer plane has the wrong size");
    expect(s.sidecar->lights.size() == f.light_groups.size(),
           "sidecar has " + std::to_string(s.sidecar->lights.size()) + " lights, file " +
               std::to_string(f.light_groups.size()) + " light groups");
    for (const auto& l : s.sidecar->lights) {
      bool found = false;
      for (const auto& g : f.light_groups) found |= g.name == l.lightgroup;
      expect(found, "no pass for light group " + l.lightgroup);
      expect(l.luminance >= 0 && std::isfinite(l.luminance), "light " + l.name + " has no valid luminance");
    }
    // The light groups sum to the beauty (every emitter is in a group); half floats: 1e-2 of the total.
    double sum_groups = 0, sum_beauty = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const float* b = &f.beauty[i * f.channels];
      sum_beauty += color::luminance(double(b[0]), double(b[1]), double(b[2]));
      for (const auto& g : f.light_groups)
        sum_groups += color::luminance(double(g.rgb[3 * i]), double(g.rgb[3 * i + 1]), double(g.rgb[3 * i + 2]));
    }
    expect(std::fabs(sum_groups - sum_beauty) <= 1e-2 * sum_beauty + 1e-6, "light groups do not sum to the beauty");
    for (std::size_t i = 0; i < n; ++i)
      if (f.normal_valid[i]) {
        const float* v = &f.normal[3 * i];
        if (std::fabs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0f) > 1e-5f) {
          expect(false, "a valid normal is not unit length");
          break;
        }
      }
    expect(s.probe && s.probe->width == 64 && s.probe->height == 32, "probe is not 64x32");
    expect(s.probe && s.probe->light_groups.size() == f.light_groups.size(), "probe lacks the light groups");
    std::printf("%s %s: %dx%d, %zu light groups, probe %dx%d, sidecar %zu lights\n", bad ? "FAIL" : "ok  ",
                name.c_str(), f.width, f.height, f.light_groups.size(), s.probe ? s.probe->width : 0,
                s.probe ? s.probe->height : 0, s.sidecar->lights.size());
  } catch (const std::exception& e) {
    std::printf("FAIL %s: %s\n", name.c_str(), e.what());
    ++bad;
  }
  return bad;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: scene_roundtrip_check DIR NAME:WxH...\n");
    return 2;
  }
  int bad = 0;
  for (int i = 2; i < argc; ++i) bad += check(argv[1], argv[i]);
  return bad ? 1 : 0;
}
