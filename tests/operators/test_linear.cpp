// linear: exposure (applied by the pipeline) then clip to [0, 1].
#include <gtest/gtest.h>

#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

TEST(Linear, IdentityThenClip) {
  const auto out = run("linear", {{0.25f, 0.5f, 0.75f}, {2.f, 1.f, 0.f}});
  EXPECT_EQ(out[0], (RGB{0.25f, 0.5f, 0.75f}));
  EXPECT_EQ(out[1], (RGB{1.f, 1.f, 0.f}));
}

TEST(Linear, ExposureInStops) {
  EXPECT_EQ(run("linear", {{0.25f, 0.125f, 0.75f}}, {}, 1.0)[0], (RGB{0.5f, 0.25f, 1.f}));
  EXPECT_EQ(run("linear", {{0.5f, 0.25f, 1.f}}, {}, -2.0)[0], (RGB{0.125f, 0.0625f, 0.25f}));
}

}  // namespace
}  // namespace cgtmo::operators::test
