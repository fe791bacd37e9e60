// Where the time of `cgtmo apply IN -o OUT.png` goes, stage by stage, on one multilayer EXR
// (bench/e2e.sh passes it): reading the beauty only versus every channel, sanitising, the operator,
// the OCIO display encoding, the 8-bit PNG write. All threads (the CLI's default); real time.
//
// Usage: bench_e2e_stages --input=FILE.exr [--output-dir=DIR] [Google Benchmark flags]
#include <OpenImageIO/imageio.h>
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cgtmo/display/display.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/parallel.h"

using namespace cgtmo;

namespace {

std::string g_input, g_output_dir = ".";

const scene::Frame& beauty() {
  static const scene::Frame f = [] {
    scene::Frame fr = io::read_beauty(g_input, "");
    scene::sanitize(fr);
    return fr;
  }();
  return f;
}

void read_beauty(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(io::read_beauty(g_input, "").beauty.data());
}

// What a reader that decodes every channel pays (as oiiotool does before --ch picks the beauty).
void read_all_channels(benchmark::State& s) {
  for (auto _ : s) {
    auto in = OIIO::ImageInput::open(g_input);
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> px(std::size_t(spec.image_pixels()) * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data())) s.SkipWithError("read failed");
    benchmark::DoNotOptimize(px.data());
  }
}

// Copies the beauty (not timed), then runs `f` on the copy.
template <class F>
void on_copy(benchmark::State& s, F&& f) {
  const scene::Frame& src = beauty();
  std::vector<float> work(src.beauty.size());
  for (auto _ : s) {
    s.PauseTiming();
    std::memcpy(work.data(), src.beauty.data(), work.size() * sizeof(float));
    s.ResumeTiming();
    f(work.data());
    benchmark::DoNotOptimize(work.data());
  }
}

void sanitize(benchmark::State& s) {
  on_copy(s, [](float* px) { scene::sanitize(px, beauty().pixel_count(), beauty().channels); });
}

void tonemap(benchmark::State& s, const std::string& op) {
  on_copy(s, [&op](float* px) {
    operators::ToneMapRequest req;
    req.op = op;
    operators::tonemap(px, beauty().pixel_count(), beauty().channels, req);
  });
}

void encode_srgb(benchmark::State& s) {
  const display::DisplayEncoder enc(display::load_config(""), "", "");
  on_copy(s, [&enc](float* px) { enc.apply(px, beauty().width, beauty().height, beauty().channels); });
}

void write_png(benchmark::State& s) {
  const scene::Frame& f = beauty();
  std::vector<float> px = f.beauty;  // display-encoded values do not change the write's cost much
  const std::string out = g_output_dir + "/bench_e2e_stages.png";
  for (auto _ : s) io::write_image_atomic(out, px.data(), f.width, f.height, f.channels);
  std::remove(out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--input=", 0) == 0) g_input = a.substr(8);
    else if (a.rfind("--output-dir=", 0) == 0) g_output_dir = a.substr(13);
    else rest.push_back(argv[i]);
  }
  if (g_input.empty()) {
    std::fprintf(stderr, "usage: bench_e2e_stages --input=FILE.exr [--output-dir=DIR] [benchmark flags]\n");
    return 2;
  }
  int n = int(rest.size());
  benchmark::Initialize(&n, rest.data());
  set_threads(0);
  std::printf("input %s: %dx%d, beauty %d channels, %d threads\n", g_input.c_str(), beauty().width, beauty().height,
              beauty().channels, thread_count());
  auto reg = [](const char* name, auto fn) {
    benchmark::RegisterBenchmark(name, fn)->UseRealTime()->Unit(benchmark::kMillisecond);
  };
  reg("read/beauty_only", read_beauty);
  reg("read/all_channels", read_all_channels);
  reg("sanitize", sanitize);
  for (const char* op : {"reinhard", "agx", "drago"})
    reg((std::string("tonemap/") + op).c_str(), [op](benchmark::State& s) { tonemap(s, op); });
  reg("encode/sRGB", encode_srgb);
  reg("write/png", write_png);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
