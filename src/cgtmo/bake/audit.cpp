#include "cgtmo/bake/audit.h"

#include <Imath/half.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::bake {

double srgb_encode(double v) {
  v = std::min(std::max(v, 0.0), 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * repro::pow(v, 1.0 / 2.4) - 0.055;
}

const std::vector<float>& audit_samples() {
  static const std::vector<float> samples = [] {
    std::vector<float> s;
    auto push = [&](float r, float g, float b) {
      s.push_back(r);
      s.push_back(g);
      s.push_back(b);
    };
    // Every finite non-negative half (bits 0x0000 .. 0x7bff): greys and pure primaries.
    for (unsigned bits = 0; bits <= 0x7bffu; ++bits) {
      Imath::half h;
      h.setBits(static_cast<unsigned short>(bits));
      const float v = float(h);
      push(v, v, v);
      push(v, 0, 0);
      push(0, v, 0);
      push(0, 0, v);
    }
    // Random colours, log-uniform per channel; mt19937's raw output keeps this portable.
    std::mt19937 rng(20240501u);
    auto uniform = [&] { return double(rng()) / 4294967296.0; };
    const double lo = -24.0, hi = repro::log2(65504.0);
    for (int i = 0; i < 120000; ++i) {
      float c[3];
      for (float& v : c) v = uniform() < 0.12 ? 0.f : float(repro::exp2(lo + (hi - lo) * uniform()));
      push(c[0], c[1], c[2]);
    }
    // Saturated hues: one channel at full, one at a fraction, one near zero, scaled over 2^-16 .. 2^16.
    for (int e = -64; e <= 64; ++e) {
      const double scale = repro::exp2(e / 4.0);
      for (int f = 0; f <= 16; ++f) {
        const double mid = f / 16.0, low = 1e-3 * (f % 4);
        const double trip[6][3] = {{1, mid, low}, {mid, 1, low}, {low, 1, mid}, {low, mid, 1}, {mid, low, 1}, {1, low, mid}};
        for (const auto& t : trip)
          push(float(std::min(65504.0, scale * t[0])), float(std::min(65504.0, scale * t[1])), float(std::min(65504.0, scale * t[2])));
      }
    }
    return s;
  }();
  return samples;
}

AuditResult audit(const OCIO::ConstCPUProcessorRcPtr& encoded, const operators::Evaluator& reference,
                  const std::vector<float>& samples) {
  const std::size_t n = samples.size() / 3;
  std::vector<float> got = samples, want = samples;
  std::vector<float> err(n);
  const int64_t chunks = 64;
  parallel_rows(chunks, [&](int64_t c0, int64_t c1) {
    const std::size_t b = n * std::size_t(c0) / chunks, e = n * std::size_t(c1) / chunks;
    if (e <= b) return;
    OCIO::PackedImageDesc desc(&got[b * 3], long(e - b), 1, 3);
    encoded->apply(desc);
    reference.apply(&want[b * 3], e - b, 3);
    for (std::size_t i = b; i < e; ++i) {
      double m = 0;
      for (int k = 0; k < 3; ++k) {
        const double g = got[i * 3 + k];
        const double d = std::isfinite(g) ? std::abs(g - srgb_encode(want[i * 3 + k])) : 1e9;
        m = std::max(m, d);
      }
      err[i] = float(m * 1023.0);
    }
  });
  AuditResult r;
  const std::size_t worst = std::size_t(std::max_element(err.begin(), err.end()) - err.begin());
  r.max_cv = err[worst];
  for (int k = 0; k < 3; ++k) r.worst[k] = samples[worst * 3 + k];
  const std::size_t q = std::size_t(std::floor(0.999 * double(n - 1)));
  std::nth_element(err.begin(), err.begin() + q, err.end());
  r.p999_cv = err[q];
  return r;
}

double ocio_throughput_mpix(const OCIO::ConstCPUProcessorRcPtr& proc) {
  const auto& s = audit_samples();
  const int w = 1920, h = 1080;
  std::vector<float> src(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < src.size(); ++i) src[i] = s[i % s.size()];
  std::vector<double> times;
  std::vector<float> buf;
  for (int run = 0; run < 5; ++run) {
    buf = src;
    const auto t0 = std::chrono::steady_clock::now();
    OCIO::PackedImageDesc desc(buf.data(), w, h, 3);
    proc->apply(desc);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return double(w) * h / times[2] / 1e6;
}

}  // namespace cgtmo::bake
