// cgtmo eval: TMQI of a tone-mapped image against its HDR source, or of every operator on the
// committed scenes (docs/quality.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cgtmo/local/evaluate.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/metrics/tmqi.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/parallel.h"
#include "cli_util.h"
#include "commands.h"
#include "stage_progress.h"

namespace cgtmo::cli {

namespace {

const char* kDescription = R"(NAME
    cgtmo eval - TMQI (tone-mapped image quality index) of tone-mapped images

SYNOPSIS
    cgtmo eval HDR.exr LDR.png [--json]
    cgtmo eval --scenes DIR [--json] [--write FILE] [--threads N]

DESCRIPTION
    With two images: TMQI (Yeganeh and Wang, IEEE TIP 2013) of the LDR image against the HDR one,
    following the published v1.0 definition: luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the
    linear HDR and of the stored LDR values on 0-255; structural fidelity S over 5 scales with an
    11x11 Gaussian window (sigma 1.5) and 'valid' filtering; statistical naturalness N from the
    LDR's mean and 11x11 block contrast; Q = 0.8012 S^0.3046 + 0.1988 N^0.7088. Prints Q, S, N.
    Both images must have the same size, at least 161x161 px (the fifth scale must hold the
    window). An 8-bit LDR is read as its code values; a float LDR (EXR) is taken as 0-1 and scaled.

    With --scenes: every DIR/<folder>/<name>.exr (with its probe and sidecar) is tone-mapped by
    global drago, bilateral, cgtmo with each filter and wls; each output is encoded to 8-bit sRGB
    and scored. Also scored: cgtmo with -p detail=illumination, and Blender's Filmic view (when
    Blender's OCIO config is installed) on the render and on cgtmo -p output=scene-linear. Prints the table; --write FILE writes it as Markdown (docs/quality.md).
)";

const char* kExamples = R"(
EXAMPLES
    cgtmo apply tests/scenes/cornell/cornell.exr -o cornell.png --op cgtmo
    cgtmo eval tests/scenes/cornell/cornell.exr cornell.png

    Regenerate docs/quality.md:
        cgtmo eval --scenes tests/scenes --write docs/quality.md
)";

// The LDR's code values: 8/16-bit files are read by OIIO as 0-1 and scaled back to 0-255.
std::vector<float> read_ldr_255(const std::string& path, int* w, int* h) {
  scene::Frame f = io::read_beauty(path, "");
  *w = f.width;
  *h = f.height;
  std::vector<float> out = scene::rgb_of(f);
  for (float& v : out) v *= 255.f;
  return out;
}

}  // namespace

int run_eval(const std::vector<std::string>& args) {
  CLI::App app{kDescription, "eval"};
  style(app);
  app.footer(kExamples);
  std::vector<std::string> files;
  std::string scenes_dir, write_path;
  bool json = false;
  int threads = 0;
  app.add_option("FILES", files, "HDR.exr LDR.png");
  app.add_option("--scenes", scenes_dir, "score every operator on every DIR/<folder>/<name>.exr");
  app.add_option("--write", write_path, "with --scenes: write the Markdown report to FILE");
  app.add_flag("--json", json, "print JSON instead of text");
  app.add_option("--threads", threads, "worker threads (0: the CPUs this process is allotted: affinity, cgroup quota, SLURM_CPUS_PER_TASK)")->check(CLI::Range(0, kMaxThreads));
  if (!parse(app, args)) return 0;
  set_threads(threads);

  if (!scenes_dir.empty()) {
    if (!files.empty()) throw UsageError("--scenes takes no image arguments");
    if (!write_path.empty()) {
      std::filesystem::path dir = std::filesystem::path(write_path).parent_path();
      std::error_code ec;
      if (!dir.empty() && !std::filesystem::is_directory(dir, ec)) throw UsageError("folder '" + dir.string() + "' does not exist");
    }
    std::vector<local::SceneScores> all;
    const auto paths = local::find_scene_files(scenes_dir);
    for (std::size_t i = 0; i < paths.size(); ++i) {
      StageProgress progress("cgtmo eval: scene " + std::to_string(i + 1) + "/" + std::to_string(paths.size()) + " " + paths[i],
                             json, std::cerr);
      all.push_back(local::evaluate_scene(paths[i], progress.callback()));
    }
    std::string command = "cgtmo eval --scenes " + scenes_dir;
    if (!write_path.empty()) command += " --write " + write_path;
    const std::string md = local::quality_markdown(all, command);
    if (!write_path.empty()) {
      const std::string tmp = write_path + ".tmp";
      {
        std::ofstream f(tmp);
        f << md;
        if (!f) throw DataError("cannot write '" + write_path + "'");
      }
      if (std::rename(tmp.c_str(), write_path.c_str()) != 0) throw DataError("cannot write '" + write_path + "'");
    }
    std::cout << (json ? local::scores_json(all) + "\n" : md);
    return 0;
  }

  if (files.size() != 2) throw UsageError("give HDR.exr and LDR.png, or --scenes DIR (see 'cgtmo eval --help')");
  scene::Frame hdr = io::read_beauty(files[0], "");
  scene::sanitize(hdr);
  int w = 0, h = 0;
  const std::vector<float> ldr = read_ldr_255(files[1], &w, &h);
  if (w != hdr.width || h != hdr.height)
    throw DataError("'" + files[1] + "' is " + std::to_string(w) + "x" + std::to_string(h) + " but '" + files[0] + "' is " +
                    std::to_string(hdr.width) + "x" + std::to_string(hdr.height));
  const metrics::TmqiResult r = metrics::tmqi_rgb(hdr.beauty.data(), hdr.channels, ldr.data(), 3, w, h);
  if (json) {
    std::cout << "{\"q\": " << r.q << ", \"s\": " << r.s << ", \"n\": " << r.n << "}\n";
  } else {
    std::printf("Q %.4f  S %.4f  N %.4f\n", r.q, r.s, r.n);
  }
  return 0;
}

}  // namespace cgtmo::cli
