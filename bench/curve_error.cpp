// The error of the fast float path (operators/curve_table.h) against the exact curve, for every
// registry operator built on a scalar curve (default parameters, image defaults from the bench
// frame). The reference is computed in double from Evaluator::curve() and the operator's
// matrices: clamp01(M_out * curve(max(M_in * rgb, 0))) per channel, or for luminance / max-RGB
// operators rgb * curve(L) / L. Inputs: 4 Mi greys log-spaced over [2^-30, 65504] (about 90 per
// table segment, so between-node maxima are hit) plus 0, and the 1920x1080 random-colour frame of
// bench_operators. Printed: the largest absolute error in display-linear [0, 1], and after the
// sRGB encoding in 8-bit code values (1.0 = one step of an 8-bit PNG).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/curve_table.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;

namespace {

std::vector<float> greys() {
  constexpr std::size_t n = std::size_t(1) << 22;
  std::vector<float> px;
  px.reserve((n + 1) * 3);
  px.insert(px.end(), {0.f, 0.f, 0.f});
  const double lo = -30.0, hi = std::log2(65504.0);
  for (std::size_t i = 0; i < n; ++i) {
    const float v = float(std::exp2(lo + (hi - lo) * double(i) / double(n - 1)));
    px.insert(px.end(), {v, v, v});
  }
  return px;
}

// The frame of bench_operators.cpp (same seed and recipe).
std::vector<float> colour_frame() {
  const std::size_t n = std::size_t(1920) * 1080;
  std::vector<float> px(n * 3);
  std::mt19937 rng(20260101u);
  std::uniform_real_distribution<float> log_lum(-3.f, 3.f), chroma(0.05f, 1.f);
  for (std::size_t i = 0; i < n; ++i) {
    const float lum = std::pow(10.f, log_lum(rng));
    float c[3] = {chroma(rng), chroma(rng), chroma(rng)};
    const float k = lum / color::luminance(c[0], c[1], c[2]);
    for (int j = 0; j < 3; ++j) px[i * 3 + j] = c[j] * k;
  }
  return px;
}

double srgb_encode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

void mat(const std::optional<color::Mat3>& m, double* c) {
  if (!m) return;
  const double r = c[0], g = c[1], b = c[2];
  for (int i = 0; i < 3; ++i) c[i] = m->m[i][0] * r + m->m[i][1] * g + m->m[i][2] * b;
}

enum class Mode { PerChannel, Luminance, MaxRGB };

// The exact output of one pixel, in double.
void reference(const operators::Evaluator& ev, Mode mode, const float* in, double* out) {
  double c[3] = {in[0], in[1], in[2]};
  mat(ev.input_matrix, c);
  if (mode == Mode::PerChannel) {
    for (double& v : c) v = ev.curve(std::max(v, 0.0));
  } else {
    double l = mode == Mode::Luminance ? color::kLumR * c[0] + color::kLumG * c[1] + color::kLumB * c[2]
                                       : std::max({c[0], c[1], c[2]});
    l = std::max(l, 0.0);
    const double s = l > 0 ? ev.curve(l) / l : 0.0;
    for (double& v : c) v = std::max(v, 0.0) * s;
  }
  mat(ev.output_matrix, c);
  for (int k = 0; k < 3; ++k) out[k] = std::clamp(c[k], 0.0, 1.0);
}

struct Errors {
  double linear = 0, code8 = 0, at = 0;
};

void measure(const operators::Evaluator& ev, Mode mode, const std::vector<float>& src, Errors& e) {
  std::vector<float> px = src;
  ev.apply(px.data(), px.size() / 3, 3);
  for (std::size_t i = 0; i < px.size(); i += 3) {
    double ref[3];
    reference(ev, mode, &src[i], ref);
    for (int k = 0; k < 3; ++k) {
      const double d = std::abs(double(px[i + k]) - ref[k]);
      if (d > e.linear) {
        e.linear = d;
        e.at = src[i + k];
      }
      e.code8 = std::max(e.code8, 255.0 * std::abs(srgb_encode(px[i + k]) - srgb_encode(ref[k])));
    }
  }
}

}  // namespace

int main() {
  const auto grey = greys();
  const auto frame = colour_frame();
  const auto stats = operators::compute_image_stats(frame.data(), frame.size() / 3, 3);
  std::printf("curve table kernel: %s\n\n", operators::CurveTable::isa());
  std::printf("| operator | mode | max abs error, linear | at input | max error after sRGB, 8-bit code values |\n");
  std::printf("|---|---|---:|---:|---:|\n");
  for (const auto& op : operators::operators_of(operators::Scope::Pixel)) {
    operators::ParamValues pv;
    const bool needs = operators::needs_image_stats(op, {});
    auto ev = operators::make_evaluator(op, {}, needs ? &stats : nullptr, &pv);
    try {
      ev->curve(1.0);
    } catch (const UsageError&) {
      std::printf("| %s | (no scalar curve: evaluated directly, no table) | | | |\n", op.name.c_str());
      continue;
    }
    Mode mode = ev->kind() == operators::Kind::PerChannel ? Mode::PerChannel : Mode::Luminance;
    const auto it = pv.texts().find("mode");
    if (it != pv.texts().end()) mode = it->second == "max-rgb" ? Mode::MaxRGB : it->second == "luminance" ? Mode::Luminance : Mode::PerChannel;
    Errors e;
    measure(*ev, mode, grey, e);
    measure(*ev, mode, frame, e);
    const char* mode_name = mode == Mode::PerChannel ? "per-channel" : mode == Mode::Luminance ? "luminance" : "max-rgb";
    std::printf("| %s | %s | %.2g | %.3g | %.2g |\n", op.name.c_str(), mode_name, e.linear, e.at, e.code8);
  }
  return 0;
}
