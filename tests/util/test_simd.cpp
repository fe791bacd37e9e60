// util/simd.h: the one run-time choice of instruction set.
#include "cgtmo/util/simd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "cgtmo/filters/simd_kernels.h"
#include "cgtmo/operators/curve_table.h"

namespace cgtmo::simd {
namespace {

TEST(Simd, BaselineIsAlwaysAvailableAndListsAreOrdered) {
  const auto isas = available_isas();
  ASSERT_FALSE(isas.empty());
  EXPECT_EQ(isas.front(), Isa::Baseline);
  EXPECT_TRUE(std::is_sorted(isas.begin(), isas.end()));
  for (Isa isa : isas) EXPECT_TRUE(compiled(isa)) << isa_name(isa);
  // A wider level needs every narrower one (the feature sets nest).
  if (available(Isa::Avx512)) EXPECT_TRUE(available(Isa::Avx2));
}

TEST(Simd, ActiveIsTheWidestAvailableCappedByTheEnvironment) {
  const Isa a = active();
  EXPECT_TRUE(available(a)) << isa_name(a);
  const char* env = std::getenv("CGTMO_ISA");
  const std::string want = env ? env : "";
  const Isa widest = available_isas().back();
  if (want.empty()) {
    EXPECT_EQ(a, widest);
  } else {
    // The cap: the named level when available, else the widest there is.
    bool named_available = false;
    for (Isa isa : available_isas()) named_available = named_available || want == isa_name(isa);
    EXPECT_EQ(std::string(isa_name(a)), named_available ? want : std::string(isa_name(widest)));
  }
}

TEST(Simd, EveryKernelFamilyReportsTheSameLevel) {
  EXPECT_EQ(std::string(operators::CurveTable::isa()), isa_name(active()));
  EXPECT_EQ(std::string(filters::simd_kernels::best().name), isa_name(active()));
}

#if !CGTMO_SIMD_X86
TEST(Simd, ABuildWithoutX86KernelsHasTheBaselineOnly) {
  EXPECT_FALSE(compiled(Isa::Avx2));
  EXPECT_FALSE(compiled(Isa::Avx512));
  EXPECT_EQ(active(), Isa::Baseline);
}
#endif

}  // namespace
}  // namespace cgtmo::simd
