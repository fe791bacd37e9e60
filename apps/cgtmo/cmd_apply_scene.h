#pragma once
// `cgtmo apply --op cgtmo|wls`: the scene operators' path of cmd_apply.cpp (they read passes,
// probe and sidecar, so they do not go through the per-pixel pipeline).
#include <map>
#include <string>

#include "cgtmo/io/read_options.h"
#include "cgtmo/pipeline/apply_file.h"
#include "apply_json.h"

namespace cgtmo::cli {

struct SceneApplyArgs {
  std::string in, out, op, layer, config, display, view;
  std::map<std::string, std::string> params;
  double exposure = 0;
  bool no_display = false, quiet = false, explain = false;
  io::OutputFormat format;             // --bit-depth, --compression
  const StageTimer* json = nullptr;    // --json: print one JSON object (with these timings) instead
  std::string colorspace;  // input colour space ("" = attribute, else scene_linear)
  std::string probe, sidecar;  // "" = beside IN
  io::ReadOptions read;
};

// `hooks`: the output's provenance record and stage progress (pipeline/apply_file.h).
int run_apply_scene(const SceneApplyArgs& a, const pipeline::FileHooks& hooks = {});

// Frame-sized planes are mapped and unmapped rather than kept in the heap once freed: glibc's
// adaptive threshold would hold up to 32 MB blocks after the first free, which raised the peak
// resident memory of a 1920x1080 frame by about 11 MB (docs/speed-vs-error.md). For single frames
// and sequences of the scene operators.
void prefer_mapped_frame_buffers();

}  // namespace cgtmo::cli
