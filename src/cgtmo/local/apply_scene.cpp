#include "cgtmo/local/apply_scene.h"

#include <cmath>
#include <memory>

#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/display/display.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/pipeline/request.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::local {

SceneApplyReport apply_scene_file(const SceneApplyOptions& o, const std::string& in, const std::string& out,
                                  const pipeline::FileHooks& hooks) {
  auto stage = [&](const char* name, int index) {
    if (hooks.on_stage) hooks.on_stage(Stage{name, index, 5});
  };
  const auto& warn = hooks.warn ? hooks.warn : o.warn;
  const operators::OperatorDef* op = &find_scene_operator(o.op);
  pipeline::check_exposure(o.exposure_ev);
  SceneApplyReport rep;
  rep.params = operators::resolve_params(*op, o.params, nullptr);
  LocalOptions lo = options_from(*op, rep.params);
  lo.exposure = repro::exp2(o.exposure_ev);
  io::check_output_path(out, in);
  io::check_output_format(out, o.output, o.encode_display);
  // The probe and sidecar beside the render are inputs too: writing over them would lose them.
  io::check_outputs_are_not_inputs({out}, {in, o.probe_path.empty() ? io::probe_path_for(in) : o.probe_path,
                                           o.sidecar_path.empty() ? io::sidecar_path_for(in) : o.sidecar_path});
  pipeline::ColourSetup colour =
      pipeline::setup_colour(o.encode_display, o.colorconfig, o.colorspace, o.display, o.view);
  const auto& config = colour.config;
  const display::DisplayEncoder* encoder = colour.encoder.get();
  if (encoder) {
    rep.config_origin = colour.config_origin;
    rep.display = encoder->display();
    rep.view = encoder->view();
  }

  stage("read", 1);
  LoadRequest req;
  req.path = in;
  req.layer = o.layer;
  req.needed_by = o.op;
  req.gbuffer = needs_gbuffer(lo);
  req.probe_path = o.probe_path;
  req.sidecar_path = o.sidecar_path;
  req.colorspace = o.colorspace;
  req.config = config;
  req.read = o.read;
  // The filter's work and then the writer's, held to the memory budget with the frame.
  const filters::FilterEntry& filter = filters::find_filter(lo.filter);
  req.work = {filter.work_bytes_per_pixel + io::kWriteBytesPerPixel, filter.work_bytes_per_column + io::kWriteBytesPerColumn,
              filter.work_bytes_per_row, "--op " + o.op + " (filter " + lo.filter + ")"};
  // A missing or foreign probe or sidecar, even one named explicitly, is a warning: the
  // statistics fall back to the image (stats.h), so the frame can still be made.
  req.explicit_companions_optional = true;
  LoadResult loaded = load_scene(req);
  rep.input_space = loaded.input_space;
  if (warn) {
    for (const auto& w : loaded.warnings) warn(w);
    for (const auto& w : loaded.companion_warnings) warn(w);
  }
  scene::Frame& s = loaded.scene;
  rep.alpha = scene::drop_alpha_without_coverage(s);
  if (!rep.alpha.empty() && warn) warn(rep.alpha);
  // A sidecar may name its probe elsewhere: known only now, still before anything is written.
  if (!s.probe.source.empty()) io::check_outputs_are_not_inputs({out}, {s.probe.source});
  rep.sanitized = loaded.beauty_report;
  rep.notes = s.notes;
  if (warn && loaded.beauty_report.total()) warn(loaded.beauty_report.describe());
  // One rule for exposure (docs/cgtmo.md): the scene is k times brighter, so its statistics are.
  const double exposure_scale = repro::exp2(o.exposure_ev);
  expose_scene(s, exposure_scale);
  stage("statistics", 2);
  LocalResult r = tone_map_local(s, lo, [&s, &stage] {
    std::vector<scene::LightGroupPlane>().swap(s.light_groups);
    s.probe = scene::Probe{};
    stage("filter", 3);
  });
  // From here on only the beauty's alpha is needed: the G-buffer and light-group planes go before
  // the output is assembled, so the encoding stage stays below the filter's peak memory.
  if (s.channels == 3) std::vector<float>().swap(s.beauty);
  for (std::vector<float>* plane : {&s.position, &s.normal, &s.albedo, &s.depth, &s.emission}) std::vector<float>().swap(*plane);
  for (std::vector<std::uint8_t>* mask : {&s.background, &s.normal_valid}) std::vector<std::uint8_t>().swap(*mask);
  std::vector<scene::LightGroupPlane>().swap(s.light_groups);
  rep.explain = std::move(r.explain);
  rep.explain.exposure_scale = exposure_scale;
  if (warn)
    for (const auto& w : rep.explain.stats.warnings) warn(w);

  rep.width = s.width;
  rep.height = s.height;
  rep.channels = s.channels;
  std::vector<float> px;
  if (rep.channels == 3) {
    px = std::move(r.rgb);
  } else {
    // The tone-mapped RGB over the beauty's, in place: its alpha stays where it is.
    for (std::size_t i = 0; i < s.pixel_count(); ++i)
      for (int c = 0; c < 3; ++c) s.beauty[i * std::size_t(rep.channels) + c] = r.rgb[3 * i + c];
    std::vector<float>().swap(r.rgb);
    px = std::move(s.beauty);
  }
  stage("encode", 4);
  if (encoder) encoder->apply(px.data(), rep.width, rep.height, rep.channels);
  stage("write", 5);
  auto metadata = io::read_passthrough_metadata(in);
  rep.metadata = io::metadata_names(*metadata);
  const io::WriteOptions w =
      pipeline::write_options(out, o.output, encoder, std::move(metadata), hooks.description, &rep.colour_tag);
  io::write_image_atomic(out, px.data(), rep.width, rep.height, rep.channels, w);
  return rep;
}

}  // namespace cgtmo::local
