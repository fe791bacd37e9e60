#include "cgtmo/pipeline/apply_file.h"

#include <cmath>
#include <cstdio>

#include "cgtmo/errors.h"
#include "cgtmo/io/chromaticities.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/scene/sanitize.h"

namespace cgtmo::pipeline {

Applier::Applier(ApplyOptions options) : options_(std::move(options)) {
  check_exposure(options_.exposure_ev);
  // Parameters are validated before any pixel is seen; image-derived defaults get placeholders.
  const auto& def = operators::find_operator(options_.op);
  const operators::ImageStats placeholder{1.0, 1.0, 1.0};
  operators::make_evaluator(def, options_.params, &placeholder);
  colour_ = setup_colour(options_.encode_display, options_.colorconfig, options_.colorspace, options_.display, options_.view);
}

ApplyReport Applier::apply_pixels(float* px, int width, int height, int channels) const {
  return process(px, width, height, channels, color::InputSpace::resolve(colour_.config, options_.colorspace, std::nullopt), options_.warn);
}

ApplyReport Applier::process(float* px, int width, int height, int channels, const color::InputSpace& space,
                             const std::function<void(const std::string&)>& warn) const {
  if (width < 1 || height < 1) throw DataError("image is empty (" + std::to_string(width) + "x" + std::to_string(height) + ")");
  if (channels != 3 && channels != 4)
    throw DataError("image has " + std::to_string(channels) + " channels; RGB (3) or RGBA (4) expected");
  ApplyReport rep;
  rep.width = width;
  rep.height = height;
  rep.channels = channels;
  const std::size_t count = std::size_t(width) * std::size_t(height);
  space.apply(px, count, channels);
  rep.input_space = space.description();
  rep.sanitized = scene::sanitize(px, count, channels);
  if (rep.sanitized.total() && warn) warn(rep.sanitized.describe());
  operators::ToneMapRequest req;
  req.op = options_.op;
  req.params = options_.params;
  req.exposure_ev = options_.exposure_ev;
  rep.tonemap = operators::tonemap(px, count, channels, req);
  if (colour_.encoder) {
    colour_.encoder->apply(px, width, height, channels);
    rep.display = colour_.encoder->display();
    rep.view = colour_.encoder->view();
    rep.config_origin = colour_.config_origin;
  }
  return rep;
}

io::WriteOptions write_options(const std::string& out, const io::OutputFormat& format, const display::DisplayEncoder* encoder,
                               std::shared_ptr<const io::Metadata> metadata, const std::string& description,
                               std::string* colour_tag) {
  io::WriteOptions w;
  w.description = description;
  w.format = format;
  w.metadata = std::move(metadata);
  const bool exr = io::check_output_path(out, "") == io::OutputKind::Exr;
  std::string tag;
  auto describe = [](const display::DisplayProfile& p) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "R %.4f,%.4f G %.4f,%.4f B %.4f,%.4f W %.4f,%.4f", p.primaries[0][0], p.primaries[0][1],
                  p.primaries[1][0], p.primaries[1][1], p.primaries[2][0], p.primaries[2][1], p.white[0], p.white[1]);
    return std::string(buf) + ", " + p.transfer_name();
  };
  if (!encoder) {
    if (exr) {
      w.linear_rec709 = true;
      tag = "chromaticities: linear Rec.709, D65";
    } else {
      const display::DisplayProfile p = display::linear_rec709_profile();
      w.icc_profile = p.icc;
      tag = "ICC profile: " + describe(p);
    }
  } else if (!exr && encoder->profile().known) {
    w.icc_profile = encoder->profile().icc;
    tag = "ICC profile: " + describe(encoder->profile());
  }
  if (colour_tag) *colour_tag = tag;
  return w;
}

ApplyReport Applier::apply_file(const std::string& in, const std::string& out, const FileHooks& hooks) const {
  io::check_output_path(out, in);
  io::check_output_format(out, options_.output, options_.encode_display);
  auto stage = [&](const char* name, int index) {
    if (hooks.on_stage) hooks.on_stage(Stage{name, index, 3});
  };
  stage("read", 1);
  // Tone-mapped in place, then encoded: the writer's buffers are the work held beside the frame.
  const io::FrameWork work{io::kWriteBytesPerPixel, io::kWriteBytesPerColumn, 0, "--op " + options_.op};
  scene::Frame frame = io::read_beauty(in, options_.layer, options_.read, work);
  const auto& warn = hooks.warn ? hooks.warn : options_.warn;
  const std::string alpha = scene::drop_alpha_without_coverage(frame);
  if (!alpha.empty() && warn) warn(alpha);
  std::string disagreement;
  const auto space = color::InputSpace::resolve(colour_.config, options_.colorspace, io::read_file_colour(in), &disagreement);
  if (!disagreement.empty() && warn) warn(disagreement);
  stage("tone-map", 2);
  ApplyReport rep = process(frame.beauty.data(), frame.width, frame.height, frame.channels, space, warn);
  rep.layer = frame.layer;
  rep.alpha = alpha;
  stage("write", 3);
  auto metadata = io::read_passthrough_metadata(in);
  rep.metadata = io::metadata_names(*metadata);
  const io::WriteOptions w = write_options(out, options_.output, colour_.encoder.get(), std::move(metadata), hooks.description, &rep.colour_tag);
  io::write_image_atomic(out, frame.beauty.data(), frame.width, frame.height, frame.channels, w);
  return rep;
}

}  // namespace cgtmo::pipeline
