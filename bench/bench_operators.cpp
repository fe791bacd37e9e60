// Speed of every registry operator on a 1920x1080 RGB float frame, at 1 and 2 threads, against
// OpenColorIO's CPU processor applying the equivalent baked transform to the same pixels in the
// same run (docs/performance.md).
//
// The frame: i.i.d. pixels whose luminance is log-uniform over [1e-3, 1e3] (six decades, as a
// CG render with dark corners and bright emitters spans) and whose chroma is a random colour
// with every channel in [0.05, 1] rescaled to that luminance; fixed seed, so every run sees the
// same data. Independent pixels are the worst case for any data-dependent branch.
//
// The OCIO peer, built in memory from the same Evaluator:
//   per-channel operators: [input matrix] -> log2 shaper [2^-16, 2^16] -> 4096-entry 1D LUT
//                          sampled from Evaluator::curve() -> [output matrix] -> clamp [0, 1];
//   mixing operators:      log2 shaper -> 65^3 3D LUT (tetrahedral) sampled from Evaluator::apply.
// OCIO's default CPU processor (default optimisation) runs it; both sides are split over rows by
// the same pool (cgtmo::parallel_rows), so "threads:N" means the same for both.
//
// Besides Google Benchmark's own lines, a table is printed at the end: Mpixel/s per operator and
// thread count, the ratio cgtmo / OCIO, and the largest |cgtmo - OCIO| on the frame (a check that
// the two transforms are equivalent, not a precision claim: LUT error dominates it).
#include <OpenColorIO/OpenColorIO.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cgtmo/color/luminance.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/util/parallel.h"

namespace OCIO = OCIO_NAMESPACE;
using namespace cgtmo;

namespace {

constexpr int kWidth = 1920, kHeight = 1080, kChannels = 3;
constexpr std::size_t kPixels = std::size_t(kWidth) * kHeight;

// log2 shaper range of the OCIO peer: covers the frame and the half-float top (65504 < 2^16).
constexpr double kShaperLo = -16.0, kShaperHi = 16.0;
constexpr int kLut1DSize = 4096;
constexpr int kLut3DSize = 65;

std::vector<float> make_frame() {
  std::vector<float> px(kPixels * kChannels);
  std::mt19937 rng(20260101u);
  std::uniform_real_distribution<float> log_lum(-3.f, 3.f), chroma(0.05f, 1.f);
  for (std::size_t i = 0; i < kPixels; ++i) {
    const float lum = std::pow(10.f, log_lum(rng));
    float c[3] = {chroma(rng), chroma(rng), chroma(rng)};
    const float k = lum / color::luminance(c[0], c[1], c[2]);
    for (int j = 0; j < 3; ++j) px[i * 3 + j] = c[j] * k;
  }
  return px;
}

const std::vector<float>& frame() {
  static const std::vector<float> f = make_frame();
  return f;
}

const operators::ImageStats& frame_stats() {
  static const operators::ImageStats s = operators::compute_image_stats(frame().data(), kPixels, kChannels);
  return s;
}

// Default parameters; image-derived defaults resolved once, here, outside any timed loop.
std::unique_ptr<operators::Evaluator> make(const operators::OperatorDef& op) {
  const bool stats = operators::needs_image_stats(op, {});
  return operators::make_evaluator(op, {}, stats ? &frame_stats() : nullptr);
}

double shaper_decode(double u) { return std::exp2(kShaperLo + u * (kShaperHi - kShaperLo)); }

OCIO::TransformRcPtr shaper() {
  auto t = OCIO::LogAffineTransform::Create();
  t->setBase(2.0);
  const double slope = 1.0 / (kShaperHi - kShaperLo), offset = -kShaperLo / (kShaperHi - kShaperLo);
  const double s[3] = {slope, slope, slope}, o[3] = {offset, offset, offset};
  t->setLogSideSlopeValue(s);
  t->setLogSideOffsetValue(o);
  return t;
}

OCIO::TransformRcPtr matrix(const color::Mat3& m) {
  auto t = OCIO::MatrixTransform::Create();
  double m44[16] = {0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m44[i * 4 + j] = m.m[i][j];
  m44[15] = 1.0;
  t->setMatrix(m44);
  return t;
}

OCIO::TransformRcPtr clamp01() {
  auto t = OCIO::RangeTransform::Create();
  t->setStyle(OCIO::RANGE_CLAMP);
  t->setMinInValue(0.0);
  t->setMaxInValue(1.0);
  t->setMinOutValue(0.0);
  t->setMaxOutValue(1.0);
  return t;
}

// The equivalent OCIO transform of an evaluator, as a CPU processor.
OCIO::ConstCPUProcessorRcPtr ocio_peer(const operators::Evaluator& ev) {
  auto group = OCIO::GroupTransform::Create();
  if (ev.kind() == operators::Kind::PerChannel) {
    if (ev.input_matrix) group->appendTransform(matrix(*ev.input_matrix));
    group->appendTransform(shaper());
    auto lut = OCIO::Lut1DTransform::Create(kLut1DSize, false);
    lut->setInterpolation(OCIO::INTERP_LINEAR);
    for (int i = 0; i < kLut1DSize; ++i) {
      const float y = float(ev.curve(shaper_decode(double(i) / (kLut1DSize - 1))));
      lut->setValue(i, y, y, y);
    }
    group->appendTransform(lut);
    if (ev.output_matrix) group->appendTransform(matrix(*ev.output_matrix));
  } else {
    group->appendTransform(shaper());
    const int n = kLut3DSize;
    std::vector<float> nodes(std::size_t(n) * n * n * 3);
    for (int r = 0; r < n; ++r)
      for (int g = 0; g < n; ++g)
        for (int b = 0; b < n; ++b) {
          float* p = &nodes[((std::size_t(r) * n + g) * n + b) * 3];
          p[0] = float(shaper_decode(double(r) / (n - 1)));
          p[1] = float(shaper_decode(double(g) / (n - 1)));
          p[2] = float(shaper_decode(double(b) / (n - 1)));
        }
    ev.apply(nodes.data(), nodes.size() / 3, 3);
    auto lut = OCIO::Lut3DTransform::Create(n);
    lut->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
    for (int r = 0; r < n; ++r)
      for (int g = 0; g < n; ++g)
        for (int b = 0; b < n; ++b) {
          const float* p = &nodes[((std::size_t(r) * n + g) * n + b) * 3];
          lut->setValue(r, g, b, p[0], p[1], p[2]);
        }
    group->appendTransform(lut);
  }
  group->appendTransform(clamp01());
  return OCIO::Config::CreateRaw()->getProcessor(group)->getDefaultCPUProcessor();
}

void run_cgtmo(const operators::Evaluator& ev, float* px) {
  parallel_rows(int64_t(kPixels), [&](int64_t b, int64_t e) {
    ev.apply(px + std::size_t(b) * kChannels, std::size_t(e - b), kChannels);
  });
}

void run_ocio(const OCIO::CPUProcessor& cpu, float* px) {
  parallel_rows(kHeight, [&](int64_t y0, int64_t y1) {
    OCIO::PackedImageDesc desc(px + std::size_t(y0) * kWidth * kChannels, kWidth, long(y1 - y0), kChannels);
    cpu.apply(desc);
  });
}

// Each iteration starts from the untouched frame (the copy is not timed).
template <class F>
void timed(benchmark::State& state, int threads, F&& apply) {
  set_threads(threads);
  std::vector<float> work(frame().size());
  for (auto _ : state) {
    state.PauseTiming();
    std::memcpy(work.data(), frame().data(), work.size() * sizeof(float));
    state.ResumeTiming();
    apply(work.data());
    benchmark::DoNotOptimize(work.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(kPixels));
}

struct Peer {
  std::unique_ptr<operators::Evaluator> ev;
  OCIO::ConstCPUProcessorRcPtr ocio;
  double max_diff = 0;  // largest |cgtmo - OCIO| over the frame
};

std::map<std::string, Peer>& peers() {
  static std::map<std::string, Peer> p;
  return p;
}

double compare(const Peer& p) {
  set_threads(0);
  std::vector<float> a = frame(), b = frame();
  run_cgtmo(*p.ev, a.data());
  run_ocio(*p.ocio, b.data());
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, double(std::abs(a[i] - b[i])));
  return d;
}

// Prints Google Benchmark's usual lines, then the summary table (medians when repeated).
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& r : runs) {
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      const auto it = r.counters.find("items_per_second");
      if (it == r.counters.end()) continue;
      std::string name = r.run_name.function_name;  // "<side>/<op>/threads:<n>"
      mpix_[name] = it->second.value / 1e6;
      // Also from the CPU time of the benchmark's thread: at 1 thread all the work runs there, so
      // this rate is what the code does when it gets the core, whatever else the machine runs.
      const double cpu_s = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      if (cpu_s > 0) cpu_mpix_[name] = double(kPixels) / cpu_s / 1e6;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n| operator | kind | cgtmo 1 thr | cgtmo 2 thr | OCIO 1 thr | OCIO 2 thr | ratio 1 thr | ratio 2 thr | ratio 1 thr, CPU time | max abs diff |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& op : operators::operators_of(operators::Scope::Pixel)) {
      const auto& p = peers()[op.name];
      double v[2][2];  // [side][threads-1]
      for (int t = 1; t <= 2; ++t) {
        v[0][t - 1] = get(mpix_, "cgtmo/" + op.name + "/threads:" + std::to_string(t));
        v[1][t - 1] = get(mpix_, "ocio/" + op.name + "/threads:" + std::to_string(t));
      }
      const std::string t1 = op.name + "/threads:1";
      const double cpu_ratio = get(cpu_mpix_, "cgtmo/" + t1) / get(cpu_mpix_, "ocio/" + t1);
      std::printf("| %s | %s | %.0f | %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2g |\n", op.name.c_str(),
                  operators::kind_name(p.ev->kind()), v[0][0], v[0][1], v[1][0], v[1][1], v[0][0] / v[1][0],
                  v[0][1] / v[1][1], cpu_ratio, p.max_diff);
    }
    std::printf("(Mpixel/s from real time, 1920x1080 RGB float; ratio = cgtmo / OCIO at the same thread count;\n"
                " the CPU-time ratio divides the 1-thread rates measured on the benchmark thread's CPU time)\n");
  }

 private:
  static double get(const std::map<std::string, double>& m, const std::string& name) {
    const auto it = m.find(name);
    return it == m.end() ? std::nan("") : it->second;
  }
  std::map<std::string, double> mpix_, cpu_mpix_;  // Mpixel/s from real time and from CPU time
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const auto& op : operators::operators_of(operators::Scope::Pixel)) {
    Peer& p = peers()[op.name];
    p.ev = make(op);
    p.ocio = ocio_peer(*p.ev);
    p.max_diff = compare(p);
    for (int t = 1; t <= 2; ++t) {
      const std::string suffix = op.name + "/threads:" + std::to_string(t);
      const operators::Evaluator* ev = p.ev.get();
      const OCIO::CPUProcessor* cpu = p.ocio.get();
      benchmark::RegisterBenchmark(("cgtmo/" + suffix).c_str(), [ev, t](benchmark::State& s) {
        timed(s, t, [ev](float* px) { run_cgtmo(*ev, px); });
      })->UseRealTime()->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("ocio/" + suffix).c_str(), [cpu, t](benchmark::State& s) {
        timed(s, t, [cpu](float* px) { run_ocio(*cpu, px); });
      })->UseRealTime()->Unit(benchmark::kMillisecond);
    }
  }
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
