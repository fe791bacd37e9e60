#include "cgtmo/bake/choose.h"

#include <cmath>
#include <sstream>

#include "cgtmo/display/display.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::bake {

operators::ImageStats reference_scene_stats() {
  operators::ImageStats s;
  s.max_channel = 16.0;
  s.max_luminance = 16.0;
  s.log_average_luminance = 0.18;
  return s;
}

double default_budget_cv(operators::Kind k) { return k == operators::Kind::PerChannel ? 0.1 : 1.0; }

std::string BakeSubject::params_text() const {
  std::ostringstream s;
  for (const auto& [k, v] : params.numbers()) s << (s.tellp() ? " " : "") << k << "=" << v;
  for (const auto& [k, v] : params.texts()) s << (s.tellp() ? " " : "") << k << "=" << (v.empty() ? "\"\"" : v);
  return s.str();
}

BakeSubject make_subject(const operators::OperatorDef& def, const std::map<std::string, std::string>& given,
                         const operators::ImageStats& stats) {
  BakeSubject s;
  s.def = &def;
  s.given = given;
  s.exact = operators::make_evaluator(def, given, &stats, &s.params);
  s.unclamped = operators::make_evaluator(def, given, &stats);
  s.unclamped->clamp_output = false;
  return s;
}

OCIO::ConstTransformRcPtr srgb_display_encoding() {
  static const OCIO::ConstTransformRcPtr t = [] {
    std::istringstream yaml(display::builtin_config_yaml());
    auto config = OCIO::Config::CreateFromStream(yaml);
    return config->getColorSpace("sRGB")->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE);
  }();
  return t;
}

OCIO::ConstCPUProcessorRcPtr encoded_processor(const BakedLut& lut) {
  auto g = view_transform(lut);
  g->appendTransform(srgb_display_encoding()->createEditableCopy());
  return OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultCPUProcessor();
}

namespace {

// The lowest shaper top (whole stops) above which the clamped curve changes the sRGB output by
// less than `tolerance` code values: inputs above it may all take the LUT's last entry.
int curve_top(const operators::Evaluator& ev, double tolerance_cv) {
  if (ev.output_matrix) return kShaperSpace.hi;  // the matrix mixes what the clamp would cut
  const double top = srgb_encode(ev.curve(65504.0));
  for (int hi = 0; hi < kShaperSpace.hi; ++hi) {
    bool flat = true;
    const double at = srgb_encode(ev.curve(repro::exp2(hi) * 0.999));
    for (double e = hi; e <= 16 && flat; e += 1.0 / 64) {
      const double v = srgb_encode(ev.curve(std::min(65504.0, repro::exp2(e))));
      flat = std::abs(v - at) * 1023 <= tolerance_cv && std::abs(top - at) * 1023 <= tolerance_cv;
    }
    if (flat) return hi;
  }
  return kShaperSpace.hi;
}

}  // namespace

Choice choose_representation(const BakeSubject& subject, double budget_cv, const Progress& progress) {
  const bool per_channel = subject.exact->kind() == operators::Kind::PerChannel;
  Choice best;
  best.audit.max_cv = INFINITY;
  int tried = 0;
  // Every candidate's error, in the order tried (cheapest first), for the fallback below.
  std::vector<std::pair<Representation, double>> errors;
  auto consider = [&](const Representation& rep) {
    ++tried;
    const auto& ev = per_channel || rep.luminance || rep.hue_steps ? *subject.exact : *subject.unclamped;
    BakedLut lut = sample_lut(ev, rep);
    const AuditResult a = audit(encoded_processor(lut), *subject.exact);
    const bool met = a.max_cv <= budget_cv;
    errors.emplace_back(rep, a.max_cv);
    if (met || a.max_cv < best.audit.max_cv) {
      best.lut = std::move(lut);
      best.audit = a;
      best.met = met;
    }
    return met;
  };
  // No candidate met the budget: the cheapest one within 1.5x the most accurate one's error, so
  // that a target out of reach does not buy a 2-5x larger file for a marginal gain.
  auto fallback = [&] {
    best.candidates_tried = tried;
    for (const auto& [rep, err] : errors)
      if (err <= 1.5 * best.audit.max_cv) {
        if (rep.dims == best.lut.rep.dims && rep.luminance == best.lut.rep.luminance && rep.hue_steps == best.lut.rep.hue_steps &&
            rep.size == best.lut.rep.size && rep.shaper.lo == best.lut.rep.shaper.lo && rep.out_log2 == best.lut.rep.out_log2 &&
            rep.warped == best.lut.rep.warped)
          break;
        const auto& ev = per_channel || rep.luminance || rep.hue_steps ? *subject.exact : *subject.unclamped;
        best.lut = sample_lut(ev, rep);
        best.audit = audit(encoded_processor(best.lut), *subject.exact);
        break;
      }
    return best;
  };
  if (per_channel) {
    const int hi = curve_top(*subject.exact, budget_cv / 4);
    for (int size : {256, 512, 1024, 2048, 4096, 8192, 16384}) {
      if (progress) progress(subject.def->name + ": 1D " + std::to_string(size));
      for (int lo = -8; lo >= -24; lo -= 2) {
        Representation r;
        r.dims = 1;
        r.size = size;
        r.shaper = {lo, hi};
        if (consider(r)) {
          best.candidates_tried = tried;
          return best;
        }
      }
    }
  } else {
    // An operator that scales RGB by curve(Y) / Y keeps chromaticity: a 1D LUT on Y (xyY) holds
    // it, exact up to float rounding in the xyY round trip; tried before any 3D LUT.
    if (scales_by_luminance(*subject.unclamped)) {
      for (int size : {256, 512, 1024, 2048, 4096, 8192, 16384}) {
        if (progress) progress(subject.def->name + ": 1D " + std::to_string(size) + " on Y (xyY)");
        for (int lo = -8; lo >= -24; lo -= 2) {
          Representation r;
          r.dims = 1;
          r.luminance = true;
          r.size = size;
          r.shaper = {lo, kShaperSpace.hi};
          if (consider(r)) {
            best.candidates_tried = tried;
            return best;
          }
        }
      }
    }
    // An operator that keeps hue in the steps of HueKeepingSteps: HSV and four 1D LUTs.
    if (hue_steps_apply(*subject.exact)) {
      for (int size : {1024, 2048, 4096, 8192, 16384}) {
        if (progress) progress(subject.def->name + ": 1D " + std::to_string(size) + " x4 in HSV");
        Representation r;
        r.dims = 1;
        r.hue_steps = true;
        r.size = size;
        if (consider(r)) {
          best.candidates_tried = tried;
          return best;
        }
      }
    }
    // 3D LUTs, at each size first with nodes uniform in the shaper, then with nodes moved by a
    // per-channel pre-curve to where the operator curves (node_warp; a 1D LUT more in the file).
    for (int size = 17; size <= kMax3DSize; size += 8) {
      if (progress) progress(subject.def->name + ": 3D " + std::to_string(size) + "^3");
      for (bool warped : {false, true})
        for (int lo = -6; lo >= (warped ? -10 : -12); lo -= 2)
          for (int out : {lo, lo + 2}) {
            if (warped && out != lo) continue;  // the stored encoding the warp was measured best with
            Representation r;
            r.dims = 3;
            r.size = size;
            r.shaper = {lo, kShaperSpace.hi};
            r.out_log2 = out;
            r.warped = warped;
            if (consider(r)) {
              best.candidates_tried = tried;
              return best;
            }
          }
    }
  }
  return fallback();
}

}  // namespace cgtmo::bake
