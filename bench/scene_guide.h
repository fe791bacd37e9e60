#pragma once
// A committed render as the filters' input, for the benchmark and the filters' scene tests: read
// as `cgtmo apply` reads it (local/scene_load.h, without the light-group passes, which only the
// statistics' Lw_max needs) and turned into filters::GuidedInput by the pipeline's own builder
// (local/filter_input.h) with the cgtmo operator's default parameters, as `cgtmo apply --op cgtmo`
// resolves them, so what is measured is what apply filters.
#include <string>

#include "cgtmo/filters/guide.h"
#include "cgtmo/local/filter_input.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"

namespace cgtmo::bench {

struct GuideFrame {
  scene::Frame scene;
  local::FilterInput filter_input;
  filters::GuidedInput input;     // filter_input.input, or a synthetic scene's view
  double lw_a = 0;                // the adaptation luminance under the signal's floor
  std::size_t channels_read = 0;  // float32 channels taken from the file (beauty + G-buffer + depth)
};

inline void load_guide_frame(const std::string& path, GuideFrame& f) {
  local::LoadRequest req;
  req.path = path;
  req.needed_by = "bench";
  req.light_groups = false;
  f.scene = local::load_scene(req).scene;
  const scene::Frame& s = f.scene;
  f.channels_read = std::size_t(s.channels) + (s.position.empty() ? 0 : 3) + (s.normal.empty() ? 0 : 3) + (s.albedo.empty() ? 0 : 3) +
                    (s.depth.empty() ? 0 : 1);
  const operators::OperatorDef& op = local::find_scene_operator("cgtmo");
  const local::LocalOptions options = local::options_from(op, operators::resolve_params(op, {}, nullptr));
  f.filter_input = local::luminance_filter_input(s, options, &f.lw_a);
  f.input = f.filter_input.input;
}

// The guide groups this frame has.
inline unsigned available_groups(const filters::GuidedInput& in) {
  return (in.position[0] ? filters::kGuidePosition : 0u) | (in.normal[0] ? filters::kGuideNormal : 0u) |
         (in.albedo[0] ? filters::kGuideAlbedo : 0u);
}

}  // namespace cgtmo::bench
