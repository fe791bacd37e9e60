#include "cgtmo/scene/sanitize.h"

#include <cmath>
#include <mutex>
#include <sstream>

#include "cgtmo/util/parallel.h"

namespace cgtmo::scene {

std::string SanitizeReport::describe() const {
  if (!total()) return {};
  std::ostringstream s;
  const char* sep = "";
  auto item = [&](std::size_t n, const char* what) {
    if (n) {
      s << sep << n << ' ' << what;
      sep = ", ";
    }
  };
  item(nan, "NaN set to 0");
  item(pos_inf, "+Inf set to 65504");
  item(neg_inf, "-Inf set to 0");
  item(negative, "negative set to 0");
  item(over_max, "above 65504 clamped");
  item(alpha, "alpha values repaired");
  return s.str();
}

static void sanitize_range(float* px, std::size_t count, int channels, SanitizeReport& r) {
  for (std::size_t i = 0; i < count; ++i, px += channels) {
    for (int c = 0; c < 3; ++c) {
      float& v = px[c];
      if (v >= 0.f && v <= kMaxInputValue) continue;  // the common case; false for NaN
      if (std::isnan(v)) { ++r.nan; v = 0.f; }
      else if (std::isinf(v)) { if (v > 0) { ++r.pos_inf; v = kMaxInputValue; } else { ++r.neg_inf; v = 0.f; } }
      else if (v < 0.f) { ++r.negative; v = 0.f; }
      else { ++r.over_max; v = kMaxInputValue; }
    }
    if (channels == 4) {
      float& a = px[3];
      if (!(a >= 0.f && a <= 1.f)) {
        ++r.alpha;
        a = std::isnan(a) ? 0.f : (a < 0.f ? 0.f : 1.f);
      }
    }
  }
}

SanitizeReport sanitize(float* px, std::size_t count, int channels) {
  SanitizeReport total;
  std::mutex m;
  parallel_rows(int64_t(count), [&](int64_t b, int64_t e) {
    SanitizeReport part;
    sanitize_range(px + std::size_t(b) * channels, std::size_t(e - b), channels, part);
    std::lock_guard<std::mutex> lock(m);
    total.nan += part.nan; total.pos_inf += part.pos_inf; total.neg_inf += part.neg_inf;
    total.negative += part.negative; total.over_max += part.over_max; total.alpha += part.alpha;
  });
  return total;
}

SanitizeReport sanitize(Frame& f) { return sanitize(f.beauty.data(), f.pixel_count(), f.channels); }

std::string drop_alpha_without_coverage(Frame& f) {
  if (f.channels != 4) return {};
  const std::size_t n = f.pixel_count();
  bool colour = false;
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = &f.beauty[i * 4];
    if (p[3] > 0.f) return {};  // some coverage: alpha kept, 0 where nothing is
    colour = colour || p[0] > 0.f || p[1] > 0.f || p[2] > 0.f;
  }
  if (!colour) return {};  // black and transparent throughout: nothing to show either way
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) f.beauty[i * 3 + std::size_t(c)] = f.beauty[i * 4 + std::size_t(c)];
  f.beauty.resize(n * 3);
  f.channels = 3;
  return "alpha is 0 at every pixel while the colour is not: alpha dropped, the output is opaque";
}

}  // namespace cgtmo::scene
