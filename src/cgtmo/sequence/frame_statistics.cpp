#include "cgtmo/sequence/frame_statistics.h"

#include <algorithm>
#include <cmath>

#include "cgtmo/local/filter_input.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/local/stats.h"
#include "cgtmo/color/input_space.h"
#include "cgtmo/color/luminance.h"
#include "cgtmo/io/chromaticities.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::sequence {

StatisticsPlan plan_statistics(const std::string& op, const std::map<std::string, std::string>& params,
                               double exposure_ev, const std::string& layer) {
  StatisticsPlan p{op, params, exposure_ev, layer, {}, {}};
  const operators::OperatorDef& def = operators::find_operator(op);
  if (def.scope == operators::Scope::Scene) {
    for (const char* name : {"lw_max", "lw_a"})
      if (!params.count(name)) p.smoothed_params.push_back(name);
    return p;
  }
  for (const auto& spec : def.params)
    if (spec.image_default != operators::ImageDefault::None && !params.count(spec.name))
      p.smoothed_params.push_back(spec.name);
  return p;
}

std::vector<double> measure_frame(const StatisticsPlan& plan, const std::string& input) {
  std::vector<double> out;
  if (plan.smoothed_params.empty()) return out;
  const float k = float(repro::exp2(plan.exposure_ev));
  const auto config = color::config_for_input(plan.colorconfig, plan.colorspace);

  const operators::OperatorDef& def = operators::find_operator(plan.op);
  if (def.scope == operators::Scope::Scene) {
    // The statistics the scene operators compute, without the G-buffer or the filter.
    const auto values = operators::resolve_params(def, plan.params, nullptr);
    local::LocalOptions lo = local::options_from(def, values);
    lo.exposure = double(k);
    local::LoadRequest req;
    req.path = input;
    req.layer = plan.layer;
    req.read = plan.read;
    req.needed_by = plan.op;
    req.gbuffer = false;
    req.colorspace = plan.colorspace;
    req.config = config;
    local::LoadResult loaded = local::load_scene(req);
    scene::Frame& s = loaded.scene;
    local::expose_scene(s, repro::exp2(plan.exposure_ev));  // as apply_scene_file: the statistics scale too
    const local::SceneStats st = local::compute_scene_stats(s, local::beauty_luminance(s), lo.adaptation_options());
    for (const auto& name : plan.smoothed_params) out.push_back(name == "lw_max" ? st.lw_max : st.lw_a);
    return out;
  }

  scene::Frame f = io::read_beauty(input, plan.layer, plan.read);
  color::InputSpace::resolve(config, plan.colorspace, io::read_file_colour(input)).apply(f.beauty, f.channels);
  scene::sanitize(f);
  for (std::size_t i = 0; i < f.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      float& v = f.beauty[i * f.channels + c];
      v = std::min(v * k, scene::kMaxInputValue);
    }
  const auto st = operators::compute_image_stats(f.beauty.data(), f.pixel_count(), f.channels);
  for (const auto& name : plan.smoothed_params)
    for (const auto& spec : def.params)
      if (spec.name == name) out.push_back(operators::image_statistic(spec.image_default, st));
  return out;
}

}  // namespace cgtmo::sequence
