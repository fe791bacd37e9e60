// Printing for `cgtmo apply --op cgtmo|wls`; the work is local::apply_scene_file.
#include "cmd_apply_scene.h"

#include <malloc.h>

#include <chrono>
#include <iostream>

#include "cgtmo/io/scene_reader.h"
#include "cgtmo/local/apply_scene.h"

namespace cgtmo::cli {

void prefer_mapped_frame_buffers() { mallopt(M_MMAP_THRESHOLD, 1 << 20); }

int run_apply_scene(const SceneApplyArgs& a, const pipeline::FileHooks& hooks) {
  const auto t0 = std::chrono::steady_clock::now();
  prefer_mapped_frame_buffers();
  local::SceneApplyOptions o;
  o.op = a.op;
  o.params = a.params;
  o.exposure_ev = a.exposure;
  o.layer = a.layer;
  o.encode_display = !a.no_display;
  o.colorconfig = a.config;
  o.display = a.display;
  o.view = a.view;
  o.output = a.format;
  o.colorspace = a.colorspace;
  o.probe_path = a.probe;
  o.sidecar_path = a.sidecar;
  o.read = a.read;
  o.warn = [&a](const std::string& msg) { std::cerr << "cgtmo apply: warning: " << a.in << ": " << msg << "\n"; };
  const local::SceneApplyReport rep = local::apply_scene_file(o, a.in, a.out, hooks);
  if (a.json) {
    nlohmann::json j = apply_json({a.in, a.out, a.op, a.exposure, a.format}, rep);
    j["timings_ms"] = a.json->durations();
    std::cout << json_text(j) << "\n";
    return 0;
  }
  if (a.explain) {
    std::cout << "reader: companions looked for in this order: " << io::kCompanionOrder << "\n";
    for (const auto& n : rep.notes) std::cout << "reader: " << n << "\n";
    for (const auto& l : local::describe(rep.explain))
      if (l.rfind("warning: ", 0) != 0) std::cout << l << "\n";  // warnings went to stderr
  }
  if (!a.quiet) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "wrote " << a.out << " (" << rep.width << "x" << rep.height << ", " << a.op;
    for (const auto& [k, v] : rep.params.texts()) std::cout << " " << k << "=" << v;
    // lw_max and lw_a are printed once, as used: "0" only means "from the scene" (--explain says from what).
    for (const auto& [k, v] : rep.params.numbers())
      if (k != "lw_max" && k != "lw_a") std::cout << " " << k << "=" << v;
    std::cout << ", Lw_max " << rep.explain.stats.lw_max << ", Lw_a " << rep.explain.stats.lw_a;
    if (!rep.display.empty()) std::cout << ", " << rep.display << "/" << rep.view << " via " << rep.config_origin;
    else std::cout << ", linear";
    std::cout << ", " << int(ms + 0.5) << " ms)\n";
  }
  return 0;
}

}  // namespace cgtmo::cli
