#include "cgtmo/operators/apply.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::operators {

ImageStats compute_image_stats(const float* px, std::size_t count, int channels) {
  double max_c = 0, max_l = 0, sum_log = 0;
  std::mutex m;
  parallel_rows(int64_t(count), [&](int64_t b, int64_t e) {
    double mc = 0, ml = 0, sl = 0;
    const float* p = px + std::size_t(b) * channels;
    for (int64_t i = b; i < e; ++i, p += channels) {
      const double l = std::max(0.0, double(color::luminance(p[0], p[1], p[2])));
      mc = std::max({mc, double(p[0]), double(p[1]), double(p[2])});
      ml = std::max(ml, l);
      sl += repro::log(kLogAverageEpsilon + l);
    }
    std::lock_guard<std::mutex> lock(m);
    max_c = std::max(max_c, mc);
    max_l = std::max(max_l, ml);
    sum_log += sl;
  });
  ImageStats s;
  s.max_channel = max_c;
  s.max_luminance = max_l;
  s.log_average_luminance = count ? repro::exp(sum_log / double(count)) : kLogAverageEpsilon;
  return s;
}

std::unique_ptr<Evaluator> make_evaluator(const OperatorDef& op, const std::map<std::string, std::string>& given,
                                          const ImageStats* stats, ParamValues* resolved) {
  if (!op.make)
    throw UsageError("'" + op.name + "' is a " + scope_name(op.scope) + " operator: it reads the render's passes, not single pixels");
  ParamValues v = resolve_params(op, given, stats);
  auto ev = op.make(v);
  if (resolved) *resolved = std::move(v);
  return ev;
}

ToneMapResult tonemap(float* px, std::size_t count, int channels, const ToneMapRequest& req) {
  ToneMapResult r;
  r.op = &find_operator(req.op);
  if (req.exposure_ev != 0.0) {
    const float k = float(repro::exp2(req.exposure_ev));
    parallel_rows(int64_t(count), [&](int64_t b, int64_t e) {
      float* p = px + std::size_t(b) * channels;
      for (int64_t i = b; i < e; ++i, p += channels) {
        p[0] = std::min(p[0] * k, 65504.f);
        p[1] = std::min(p[1] * k, 65504.f);
        p[2] = std::min(p[2] * k, 65504.f);
      }
    });
  }
  r.used_image_stats = needs_image_stats(*r.op, req.params);
  if (r.used_image_stats) r.stats = compute_image_stats(px, count, channels);
  auto ev = make_evaluator(*r.op, req.params, r.used_image_stats ? &r.stats : nullptr, &r.params);
  r.kind = ev->kind();
  const Evaluator& e = *ev;
  parallel_rows(int64_t(count), [&](int64_t b, int64_t end) {
    e.apply(px + std::size_t(b) * channels, std::size_t(end - b), std::size_t(channels));
  });
  return r;
}

}  // namespace cgtmo::operators
