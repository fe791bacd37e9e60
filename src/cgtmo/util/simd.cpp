#include "cgtmo/util/simd.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace cgtmo::simd {

namespace {

// The CPU's widest level among those compiled, detected once.
Isa cpu_level() {
#if CGTMO_SIMD_X86
  __builtin_cpu_init();
  // The same features as CGTMO_SIMD_AVX2_TARGET and CGTMO_SIMD_AVX512_TARGET.
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
  return avx512 ? Isa::Avx512 : avx2 ? Isa::Avx2 : Isa::Baseline;
#else
  return Isa::Baseline;
#endif
}

Isa cpu() {
  static const Isa level = cpu_level();
  return level;
}

}  // namespace

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::Avx2: return "avx2";
    case Isa::Avx512: return "avx512";
    case Isa::Baseline: break;
  }
  return "baseline";
}

bool compiled(Isa isa) { return isa == Isa::Baseline || CGTMO_SIMD_X86; }

bool available(Isa isa) { return compiled(isa) && int(isa) <= int(cpu()); }

std::vector<Isa> available_isas() {
  std::vector<Isa> out;
  for (Isa isa : {Isa::Baseline, Isa::Avx2, Isa::Avx512})
    if (available(isa)) out.push_back(isa);
  return out;
}

Isa active() {
  static const Isa chosen = [] {
    const char* env = std::getenv("CGTMO_ISA");
    const Isa widest = cpu();
    if (!env || !*env) return widest;
    const std::string want = env;
    for (Isa isa : {Isa::Baseline, Isa::Avx2, Isa::Avx512})
      if (want == isa_name(isa)) return int(isa) < int(widest) ? isa : widest;
    std::fprintf(stderr, "cgtmo: warning: CGTMO_ISA='%s' is not baseline, avx2 or avx512: ignored\n", env);
    return widest;
  }();
  return chosen;
}

}  // namespace cgtmo::simd
