#pragma once
// `cgtmo apply --op cgtmo|wls`: the scene operators' path of cmd_apply.cpp (they read passes,
// probe and sidecar, so they do not go through the per-pixel pipeline).
#include <map>
#include <string>

namespace cgtmo::cli {

struct SceneApplyArgs {
  std::string in, out, op, layer, config, display, view;
  std::map<std::string, std::string> params;
  double exposure = 0;
  bool no_display = false, quiet = false, explain = false;
};

int run_apply_scene(const SceneApplyArgs& a);

}  // namespace cgtmo::cli
