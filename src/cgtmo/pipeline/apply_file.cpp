#include "cgtmo/pipeline/apply_file.h"

#include <cmath>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::pipeline {

Applier::Applier(ApplyOptions options) : options_(std::move(options)) {
  if (!std::isfinite(options_.exposure_ev) || std::abs(options_.exposure_ev) > 64)
    throw UsageError("exposure must be within [-64, 64] stops");
  if (!options_.encode_display && (!options_.display.empty() || !options_.view.empty()))
    throw UsageError("a display or view cannot be combined with linear (unencoded) output");
  // Parameters are validated before any pixel is seen; image-derived defaults get placeholders.
  const auto& def = operators::find_operator(options_.op);
  const operators::ImageStats placeholder{1.0, 1.0, 1.0};
  operators::make_evaluator(def, options_.params, &placeholder);
  if (options_.encode_display)
    encoder_ = std::make_unique<display::DisplayEncoder>(
        display::load_config(options_.colorconfig, &config_origin_), options_.display, options_.view);
}

ApplyReport Applier::apply_pixels(float* px, int width, int height, int channels) const {
  if (width < 1 || height < 1) throw DataError("image is empty (" + std::to_string(width) + "x" + std::to_string(height) + ")");
  if (channels != 3 && channels != 4)
    throw DataError("image has " + std::to_string(channels) + " channels; RGB (3) or RGBA (4) expected");
  ApplyReport rep;
  rep.width = width;
  rep.height = height;
  rep.channels = channels;
  const std::size_t count = std::size_t(width) * std::size_t(height);
  rep.sanitized = scene::sanitize(px, count, channels);
  if (rep.sanitized.total() && options_.warn) options_.warn(rep.sanitized.describe());
  operators::ToneMapRequest req;
  req.op = options_.op;
  req.params = options_.params;
  req.exposure_ev = options_.exposure_ev;
  rep.tonemap = operators::tonemap(px, count, channels, req);
  if (encoder_) {
    encoder_->apply(px, width, height, channels);
    rep.display = encoder_->display();
    rep.view = encoder_->view();
    rep.config_origin = config_origin_;
  }
  return rep;
}

ApplyReport Applier::apply_file(const std::string& in, const std::string& out, const FileHooks& hooks) const {
  io::check_output_path(out, in);
  auto stage = [&](const char* name, int index) {
    if (hooks.on_stage) hooks.on_stage(Stage{name, index, 3});
  };
  stage("read", 1);
  scene::Frame frame = io::read_beauty(in, options_.layer, options_.read);
  stage("tone-map", 2);
  ApplyReport rep = apply_pixels(frame.beauty.data(), frame.width, frame.height, frame.channels);
  rep.layer = frame.layer;
  stage("write", 3);
  io::write_image_atomic(out, frame.beauty.data(), frame.width, frame.height, frame.channels, hooks.description);
  return rep;
}

}  // namespace cgtmo::pipeline
