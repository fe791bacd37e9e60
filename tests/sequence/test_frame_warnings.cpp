// src/cgtmo/sequence/frame_warnings.cpp: a sequence's warnings grouped across its frames.
#include "cgtmo/sequence/frame_warnings.h"

#include <gtest/gtest.h>

#include <thread>

using namespace cgtmo::sequence;

TEST(FrameWarnings, TheSameWarningOnSeveralFramesIsOneLineWithTheirRanges) {
  FrameWarnings w(FramePattern::parse("renders/shot.####.exr"));
  for (long f : {1, 2, 3, 5})
    w.add(f, "no adaptation probe ('renders/shot." + std::string(f < 10 ? "000" : "00") + std::to_string(f) +
                 ".probe.exr' does not exist)");
  w.add(4, "12 NaN pixels set to 0");
  const auto lines = w.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "frames 1-3,5: no adaptation probe ('renders/shot.####.probe.exr' does not exist)");
  EXPECT_EQ(lines[1], "frame 4: 12 NaN pixels set to 0");
}

TEST(FrameWarnings, NumbersThatAreNotTheFramesFileNameStay) {
  FrameWarnings w(FramePattern::parse("####.exr"));
  w.add(12, "'0012.exr': 12 pixels above 65504, 0012 in the text");
  EXPECT_EQ(w.lines()[0], "frame 12: '####.exr': 12 pixels above 65504, 0012 in the text");
}

TEST(FrameWarnings, FramesWarnFromManyThreads) {
  FrameWarnings w(FramePattern::parse("a.#.exr"));
  std::vector<std::thread> pool;
  for (int t = 0; t < 4; ++t)
    pool.emplace_back([&w, t] {
      for (long f = t; f < 400; f += 4) w.add(f, "same");
    });
  for (auto& t : pool) t.join();
  const auto groups = w.groups();
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].frames.size(), 400u);
  EXPECT_EQ(w.lines()[0], "frames 0-399: same");
}
