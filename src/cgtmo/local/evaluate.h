#pragma once
// TMQI of the operators on committed scenes: the data behind `cgtmo eval --scenes` and
// docs/quality.md (laid out like Table 1 of the CG-TMO paper). Each method's output is
// display-encoded (sRGB, the built-in config) and quantised to 8 bits, as a PNG would hold it,
// then scored against the scene's HDR beauty.
#include <string>
#include <vector>

#include "cgtmo/local/stats.h"
#include "cgtmo/metrics/tmqi.h"
#include "cgtmo/util/progress.h"

namespace cgtmo::local {

struct MethodScore {
  std::string method;  // drago, bilateral, cgtmo-exact, cgtmo-poisson, cgtmo-fast, wls, ...
  metrics::TmqiResult tmqi;
  double ms = 0;       // tone-mapping time (not TMQI), informative only
};

struct SceneScores {
  std::string name, path;
  int width = 0, height = 0;
  std::vector<MethodScore> scores;
  SceneStats stats_log, stats_harmonic;  // the scene statistics under both Lw_a choices (whole probe)
  SceneStats stats_view;                 // Lw_a from the probe under the view lobe (log-average)
  std::vector<std::string> notes;        // reader notes (missing passes/companions)
  const MethodScore* find(const std::string& method) const;
};

// The methods of the main table, in column order, then the adaptation study's two columns, then
// the adaptation region study's (view lobe and image; the whole probe is cgtmo-fast/log).
const std::vector<std::string>& table_methods();
const std::vector<std::string>& adaptation_methods();
const std::vector<std::string>& region_methods();

// Every render DIR/<folder>/<name>.exr (probes, *.probe.exr, excluded), sorted by path.
std::vector<std::string> find_scene_files(const std::string& dir);

// Scores every method on one scene; `progress` hears each method as a stage as it starts (one
// scene takes minutes).
SceneScores evaluate_scene(const std::string& exr_path, const StageCallback& progress = {});

// 8-bit sRGB (0-255 values, 3 channels) of display-linear RGB, through the built-in config.
std::vector<float> encode_ldr_255(const std::vector<float>& rgb_linear, int width, int height);

// A digest (16 hex digits) of what the report is computed from besides the code: every file in the
// folders of `scene_paths` (renders, probes, sidecars) and Blender's OCIO config (the Filmic column).
std::string scenes_inputs_digest(const std::vector<std::string>& scene_paths);

// docs/quality.md: the tables, the targets and whether each is met, the regenerating command.
std::string quality_markdown(const std::vector<SceneScores>& scenes, const std::string& command);
std::string scores_json(const std::vector<SceneScores>& scenes);

}  // namespace cgtmo::local
