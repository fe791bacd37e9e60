// cgtmo info: what a file holds, grouped by layer; what the scene reader makes of it (passes,
// light groups, probe, sidecar, background, luminance range); which operators can run on it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <vector>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/sequence/provenance.h"
#include "cgtmo/util/allocation.h"
#include "cgtmo/util/text.h"
#include "cli_util.h"
#include "commands.h"

namespace cgtmo::cli {

namespace {

const char* kDescription = R"(NAME
    cgtmo info - the layers, passes, light groups, probe and sidecar of a render

SYNOPSIS
    cgtmo info IN [--probe FILE] [--sidecar FILE] [--layer NAME] [--window display|data]
               [--exr-view NAME] [--pass ROLE=LAYER]... [--header-only] [--max-memory MB]
    cgtmo info --allocation [IN]

DESCRIPTION
    Channels are grouped by layer (the part of the name before the last dot: ViewLayer.Combined,
    ViewLayer.Normal, ...), with the beauty layer that 'cgtmo apply' would pick marked.

    Then the scene reader's view of the file: which channels it maps onto each pass (Blender's
    ViewLayer.Position.X or generic P.x, N.x, albedo.r, Z, ...), the background fraction (depth
    at or above 1e9; Blender writes 1e10), normals without a usable length, every light group
    with its peak luminance and whether it is zero everywhere, the luminance range of the beauty
    (Rec.709 Y; all pixels and foreground only), and the companions found by convention beside
    IN.exr: IN.probe.exr (64x32 equirectangular adaptation probe) and IN.json (the sidecar with
    the camera and every light's luminance). Reading the probe or sidecar fails loudly when they
    are malformed, so 'cgtmo info' also validates a scene before 'cgtmo apply' uses it.

    An image that cgtmo wrote also lists what made it: the operator, the parameters given, the
    exposure, the colour management, and the size and time of every file the frame read (the
    record a resumed sequence compares, docs/sequences.md).

    Windows: each part's data window (the pixels stored) and display window (the frame) are
    listed when they differ or when the file has several parts. The passes are read on the
    display window unless --window data (the beauty's data window); a pass outside its part's
    data window reads 0, depth reads background (docs/exr-inputs.md). The image size printed
    under "read:" is the size 'cgtmo apply' writes with the same --window.

    --pass ROLE=LAYER names the layer for a role when the automatic mapping does not know the
    renderer's AOV names (ROLE: position, normal, albedo, emission, depth, lightgroup:NAME;
    LAYER.X,Y,Z or LAYER.R,G,B, for depth the channel LAYER or LAYER.Z); the passes table then
    shows the channels each role got, marked with (--pass).

    --header-only reads no pixels (the layer listing only).

    --allocation prints what this process is allotted and what set it: the CPUs (the fewest of
    the affinity mask, the cgroup CPU quota and SLURM_CPUS_PER_TASK), which size the thread
    pool and how many frames of a sequence run at once, and the memory (the least of the RAM,
    the cgroup memory limit, SLURM_MEM_PER_NODE and SLURM_MEM_PER_CPU x CPUs), half of which
    is the readers' budget. IN is optional with it.
)";

struct LumStats {
  double min = INFINITY, max = -INFINITY, sum = 0;
  std::size_t n = 0;
  void add(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
    sum += v;
    ++n;
  }
  std::string text() const {
    if (!n) return "none";
    char buf[128];
    std::snprintf(buf, sizeof buf, "min %.4g, max %.4g, mean %.4g", min, max, sum / double(n));
    return buf;
  }
};

LumStats luminance_of(const float* rgb, std::size_t npx, int stride, const std::vector<std::uint8_t>* skip) {
  LumStats s;
  for (std::size_t i = 0; i < npx; ++i) {
    if (skip && !skip->empty() && (*skip)[i]) continue;
    const float* p = rgb + i * std::size_t(stride);
    s.add(color::luminance(double(p[0]), double(p[1]), double(p[2])));
  }
  return s;
}

std::string join(const std::vector<std::string>& v, const char* sep = ",") {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

void print_layers(const io::FileChannels& fc, const std::string& beauty, bool has_beauty) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> layers;
  for (const auto& n : fc.names) {
    const auto dot = n.rfind('.');
    const std::string l = dot == std::string::npos ? "" : n.substr(0, dot);
    if (!layers.count(l)) order.push_back(l);
    layers[l].push_back(dot == std::string::npos ? n : n.substr(dot + 1));
  }
  std::cout << "layers:\n";
  for (const auto& l : order) {
    std::cout << "  " << (l.empty() ? "(top level)" : l) << ":";
    for (const auto& c : layers[l]) std::cout << " " << c;
    if (has_beauty && l == beauty) std::cout << "   <- beauty";
    std::cout << "\n";
  }
}

void print_scene(const io::Scene& s, const io::ReadOptions& read) {
  const io::Window window = read.window;
  auto chosen = [&read](const std::string& role) {
    for (const auto& o : read.passes)
      if (o.role == role) return std::string(" (--pass)");
    return std::string();
  };
  using scene::Pass;
  const scene::Frame& f = s.frame;
  const std::size_t npx = f.pixel_count();
  std::cout << "read: " << io::window_name(window) << " window, " << io::rect_text(s.window) << "\n";
  if (!s.views.empty()) {
    std::cout << "views:";
    for (const auto& v : s.views) std::cout << " " << v << (v == s.view ? " (read)" : "");
    std::cout << "\n";
  }
  std::cout << "passes (" << s.channels.scheme << " names):\n";
  auto row = [&](Pass p, const std::vector<std::string>& names, const std::string& extra) {
    std::printf("  %-10s %s%s%s\n", scene::pass_name(p), names.empty() ? "-" : join(names).c_str(), chosen(scene::pass_name(p)).c_str(),
                extra.c_str());
  };
  row(Pass::Beauty, s.channels.beauty, "");
  std::string bg;
  if (!f.background.empty()) {
    const auto n = std::count(f.background.begin(), f.background.end(), std::uint8_t(1));
    char buf[96];
    std::snprintf(buf, sizeof buf, "   background %.2f %% (%zu px)", 100.0 * double(n) / double(npx), std::size_t(n));
    bg = buf;
  }
  row(Pass::Depth, s.channels.depth.empty() ? std::vector<std::string>{} : std::vector<std::string>{s.channels.depth}, bg);
  row(Pass::Position, s.channels.position, "");
  std::string nn;
  if (!f.normal.empty()) nn = "   " + std::to_string(s.invalid_normals) + " foreground px without a usable normal";
  row(Pass::Normal, s.channels.normal, nn);
  row(Pass::Albedo, s.channels.albedo, "");
  row(Pass::Emission, s.channels.emission, "");
  const auto other = scene::unmapped_channels(s.file_channels, s.channels);
  if (!other.empty()) std::cout << "  other      " << join(other, ", ") << "\n";

  std::cout << "light groups: " << (f.light_groups.empty() ? "none" : std::to_string(f.light_groups.size())) << "\n";
  for (const auto& g : f.light_groups) {
    const LumStats st = luminance_of(g.rgb.data(), npx, 3, nullptr);
    if (g.all_zero)
      std::printf("  %-16s zero everywhere", g.name.c_str());
    else
      std::printf("  %-16s peak luminance %.4g", g.name.c_str(), st.max);
    std::printf("%s", chosen("lightgroup:" + g.name).c_str());
    if (s.sidecar) {
      if (const scene::LightInfo* l = s.sidecar->light_for_group(g.name))
        std::printf("   sidecar: %s, luminance %.6g%s", l->type.c_str(), l->luminance,
                    l->in_frame ? (*l->in_frame ? ", in frame" : ", not in frame") : "");
    }
    std::printf("\n");
  }
  std::cout << "luminance: all " << luminance_of(f.beauty.data(), npx, f.channels, nullptr).text();
  if (!f.background.empty()) std::cout << "; foreground " << luminance_of(f.beauty.data(), npx, f.channels, &f.background).text();
  std::cout << "\n";

  if (s.probe) {
    const scene::Frame& p = *s.probe;
    std::cout << "probe: " << s.probe_path << ", " << p.width << "x" << p.height << " equirectangular, luminance "
              << luminance_of(p.beauty.data(), p.pixel_count(), p.channels, nullptr).text() << "\n";
  } else {
    std::cout << "probe: none (looked for " << s.probe_path << ")\n";
  }
  if (s.sidecar) {
    const scene::Sidecar& sc = *s.sidecar;
    const double deg = 180.0 / M_PI;
    std::printf("sidecar: %s%s%s, camera %dx%d fov %.2f x %.2f deg, %zu lights\n", s.sidecar_path.c_str(),
                sc.scene.empty() ? "" : ", scene ", sc.scene.c_str(), sc.camera.width, sc.camera.height,
                sc.camera.fov_x_rad * deg, sc.camera.fov_y_rad * deg, sc.lights.size());
    double max_l = 0;
    std::string max_name;
    for (const auto& l : sc.lights)
      if (l.luminance > max_l) max_l = l.luminance, max_name = l.name;
    if (!max_name.empty()) std::printf("  brightest light: %s, luminance %.6g\n", max_name.c_str(), max_l);
  } else {
    std::cout << "sidecar: none (looked for " << s.sidecar_path << ")\n";
  }
  for (const auto& w : s.warnings) std::cout << "note: " << w << "\n";
}

void print_windows(const std::string& path) {
  const std::vector<io::Part> parts = io::read_parts(path);
  bool differ = parts.size() > 1;
  for (const auto& p : parts) differ = differ || p.data != p.display;
  if (!differ) return;
  std::cout << "windows:\n";
  for (const auto& p : parts) {
    std::cout << "  part " << p.index << (p.name.empty() ? "" : " '" + p.name + "'") << ": data " << io::rect_text(p.data)
              << ", display " << io::rect_text(p.display) << "\n";
  }
}

void print_allocation() {
  const Allocation& a = process_allocation();
  const double mb = 1024.0 * 1024.0;
  std::printf("cpus: %d (%s)\n", a.cpus, a.cpus_source.c_str());
  const bool own = io::memory_budget() != io::default_memory_budget();
  std::printf("memory: %.0f MB (%s); readers' budget %.0f MB (%s)\n", double(a.memory_bytes) / mb, a.memory_source.c_str(),
              double(io::memory_budget()) / mb, own ? "--max-memory" : "half");
}

}  // namespace

int run_info(const std::vector<std::string>& args) {
  CLI::App app{kDescription, "info"};
  style(app);
  app.footer("\nEXAMPLES\n    cgtmo info tests/scenes/cornell/cornell.exr\n"
             "    cgtmo info render.exr --probe render_env.exr --sidecar render_camera.json\n");
  std::string in, probe, sidecar, layer, window = "display";
  io::ReadOptions read;
  std::vector<std::string> pass_args;
  bool header_only = false, allocation = false;
  app.add_option("IN", in, "input image (required unless --allocation)");
  app.add_option("--probe", probe, "adaptation probe (default: IN.probe.exr when present)");
  app.add_option("--sidecar", sidecar, "JSON sidecar (default: IN.json when present)");
  app.add_option("--layer", layer, "beauty layer prefix, e.g. ViewLayer");
  app.add_option("--window", window, "display (default) or data: the window the passes are read on")->capture_default_str();
  app.add_option("--pass", pass_args, "ROLE=LAYER: the layer for a role (position, normal, albedo, emission, depth, lightgroup:NAME); repeatable");
  app.add_option("--exr-view", read.view, "multi-view (stereo) EXR: the view to read (default: the file's first view)");
  app.add_flag("--header-only", header_only, "list the layers only; read no pixels");
  app.add_flag("--allocation", allocation, "print the CPUs and memory this process is allotted, and what set them");
  double max_memory_mb = 0;
  add_max_memory_option(app, max_memory_mb);
  if (!parse(app, args)) return 0;
  apply_max_memory(max_memory_mb);
  read.window = io::parse_window(window);
  for (const auto& p : pass_args) read.passes.push_back(scene::parse_pass_override(p));
  if (allocation) {
    print_allocation();
    if (in.empty()) return 0;
  }
  if (in.empty()) throw UsageError("IN is required (see 'cgtmo info --help')");

  const io::FileChannels fc = io::read_header(in);
  std::cout << in << ": " << fc.width << "x" << fc.height << ", " << fc.format << ", " << fc.names.size() << " channels\n";
  // A cgtmo output says what made it (sequence/provenance.h): one field per line.
  if (const auto made = sequence::Provenance::parse(io::read_description(in, io::ReaderBy::ContentThenExtension))) {
    std::cout << "made by cgtmo:\n";
    for (const auto& [k, v] : made->fields) std::cout << "  " << printable(k) << ": " << printable(v) << "\n";  // one line each
  }
  std::string beauty, no_beauty;
  bool has_beauty = true;
  try {
    beauty = io::find_beauty(fc, layer).prefix;
  } catch (const DataError& e) {
    has_beauty = false;
    no_beauty = e.what();
  }
  print_layers(fc, beauty, has_beauty);
  print_windows(in);
  if (!has_beauty) {
    std::cout << "beauty: none (" << printable(no_beauty) << "): no operator can run on this file as it is\n";
    return 0;
  }
  std::cout << "beauty: " << (beauty.empty() ? "R,G,B" : beauty) << "\n";
  if (!header_only) {
    io::SceneRequest req;
    req.required = scene::Pass::Beauty;
    req.optional = scene::Pass::Depth | scene::Pass::Normal | scene::Pass::LightGroups;
    req.layer = layer;
    req.needed_by = "info";
    req.probe_path = probe;
    req.sidecar_path = sidecar;
    req.read = read;
    print_scene(io::read_scene(in, req), read);
  }
  std::cout << "operators that can run:";
  for (const auto& op : operators::operators_of(operators::Scope::Pixel)) std::cout << " " << op.name;
  std::cout << "\n";
  return 0;
}

}  // namespace cgtmo::cli
