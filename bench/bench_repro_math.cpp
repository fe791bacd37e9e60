// The price of reproducible elementary functions: cgtmo::repro (util/repro_math.h, the same bits on
// every CPU) against glibc's (fastest variant for this CPU) on the same inputs, one call per value.
// Each benchmark also reports max_ulp, the largest distance of its results from long-double libm
// over those inputs, so speed and error read side by side (docs/performance.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "cgtmo/util/repro_math.h"

namespace {

constexpr int kValues = 4096;

struct Range {
  double lo, hi;
};

std::vector<double> inputs(Range r) {
  std::vector<double> v(kValues);
  for (int i = 0; i < kValues; ++i) v[std::size_t(i)] = r.lo + (r.hi - r.lo) * (i + 0.5) / kValues;
  return v;
}

int64_t ordered(double x) {
  int64_t i;
  std::memcpy(&i, &x, sizeof i);
  return i < 0 ? INT64_MIN - i : i;
}

double ulp_distance(double got, long double want) {
  const int64_t d = ordered(got) - ordered(double(want));
  return double(d < 0 ? -d : d);
}

// run(state, inputs, f, reference): times f over the inputs and reports its max ulp error.
template <class F, class R>
void run(benchmark::State& state, Range range, F f, R reference) {
  const std::vector<double> x = inputs(range);
  double worst = 0;
  for (double v : x) worst = std::max(worst, ulp_distance(f(v), reference((long double)v)));
  for (auto _ : state) {
    double sum = 0;
    for (double v : x) sum += f(v);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kValues);
  state.counters["max_ulp"] = worst;
}

// Ranges the library uses them on: log luminance, curve exponents, angles of the hue tables.
#define CGTMO_BENCH_PAIR(name, lo, hi, repro_call, std_call, ref_call)                                 \
  void repro_##name(benchmark::State& s) {                                                            \
    run(s, {lo, hi}, [](double v) { return repro_call; }, [](long double v) { return ref_call; });   \
  }                                                                                                   \
  void glibc_##name(benchmark::State& s) {                                                            \
    run(s, {lo, hi}, [](double v) { return std_call; }, [](long double v) { return ref_call; });     \
  }                                                                                                   \
  BENCHMARK(repro_##name);                                                                            \
  BENCHMARK(glibc_##name);

CGTMO_BENCH_PAIR(exp, -30.0, 30.0, cgtmo::repro::exp(v), std::exp(v), expl(v))
CGTMO_BENCH_PAIR(exp2, -30.0, 30.0, cgtmo::repro::exp2(v), std::exp2(v), exp2l(v))
CGTMO_BENCH_PAIR(log, 1e-6, 1e4, cgtmo::repro::log(v), std::log(v), logl(v))
CGTMO_BENCH_PAIR(log2, 1e-6, 1e4, cgtmo::repro::log2(v), std::log2(v), log2l(v))
CGTMO_BENCH_PAIR(log10, 1e-6, 1e4, cgtmo::repro::log10(v), std::log10(v), log10l(v))
CGTMO_BENCH_PAIR(pow, 1e-4, 64.0, cgtmo::repro::pow(v, 0.4545), std::pow(v, 0.4545), powl(v, 0.4545L))
CGTMO_BENCH_PAIR(sin, -6.3, 6.3, cgtmo::repro::sin(v), std::sin(v), sinl(v))
CGTMO_BENCH_PAIR(atan2, -10.0, 10.0, cgtmo::repro::atan2(v, 0.7), std::atan2(v, 0.7), atan2l(v, 0.7L))

}  // namespace

BENCHMARK_MAIN();
