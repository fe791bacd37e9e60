// Linked into the test binaries that ctest runs once per SIMD level (cgtmo_add_isa_variants in
// tests/CMakeLists.txt): with CGTMO_ISA naming a level this build or CPU does not have, the kernels
// would fall back to a narrower one and the run would test nothing new, so it reports itself
// skipped instead (ctest matches the line below).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cgtmo/util/simd.h"

namespace {

class IsaVariant : public ::testing::Environment {
 public:
  void SetUp() override {
    const char* env = std::getenv("CGTMO_ISA");
    if (!env || !*env) return;
    const std::string active = cgtmo::simd::isa_name(cgtmo::simd::active());
    if (active != env) {
      std::printf("CGTMO_ISA=%s not available in this build or on this CPU (runs %s)\n", env, active.c_str());
      GTEST_SKIP();
    }
  }
};

const auto* const kRegistered = ::testing::AddGlobalTestEnvironment(new IsaVariant);

}  // namespace
