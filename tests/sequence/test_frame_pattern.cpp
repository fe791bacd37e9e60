#include "cgtmo/sequence/frame_pattern.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "cgtmo/errors.h"

using cgtmo::UsageError;
using cgtmo::sequence::FramePattern;
using cgtmo::sequence::format_frame_ranges;
using cgtmo::sequence::parse_frame_range;

TEST(FramePattern, HashesPadToTheirCount) {
  const auto p = FramePattern::parse("shot.####.exr");
  EXPECT_EQ(p.format(1), "shot.0001.exr");
  EXPECT_EQ(p.format(240), "shot.0240.exr");
  EXPECT_EQ(p.format(123456), "shot.123456.exr");  // wider frames are not truncated
}

TEST(FramePattern, PrintfAndAtStyles) {
  EXPECT_EQ(FramePattern::parse("a/b.%04d.png").format(7), "a/b.0007.png");
  EXPECT_EQ(FramePattern::parse("b.%d.png").format(7), "b.7.png");
  EXPECT_EQ(FramePattern::parse("b.@@@.png").format(7), "b.007.png");
  EXPECT_EQ(FramePattern::parse("b_#.png").format(12), "b_12.png");
  EXPECT_EQ(FramePattern::parse("neg.####.exr").format(-3), "neg.-0003.exr");
}

TEST(FramePattern, RejectsMissingOrRepeatedTokens) {
  EXPECT_FALSE(FramePattern::is_pattern("plain.exr"));
  EXPECT_FALSE(FramePattern::is_pattern("100%.exr"));
  EXPECT_TRUE(FramePattern::is_pattern("x.%03d.exr"));
  EXPECT_THROW(FramePattern::parse("plain.exr"), UsageError);
  EXPECT_THROW(FramePattern::parse("a.##.b.##.exr"), UsageError);
  EXPECT_THROW(FramePattern::parse("a.%04d.%d.exr"), UsageError);
  EXPECT_THROW(FramePattern::parse("a.#############.exr"), UsageError);
}

TEST(FrameRange, SimpleSteppedAndLists) {
  EXPECT_EQ(parse_frame_range("1-5"), (std::vector<long>{1, 2, 3, 4, 5}));
  EXPECT_EQ(parse_frame_range("1-10x3"), (std::vector<long>{1, 4, 7, 10}));
  EXPECT_EQ(parse_frame_range("7"), (std::vector<long>{7}));
  EXPECT_EQ(parse_frame_range("1-3,10,2,20-24x2"), (std::vector<long>{1, 2, 3, 10, 20, 22, 24}));
  EXPECT_EQ(parse_frame_range("-2-1"), (std::vector<long>{-2, -1, 0, 1}));
}

TEST(FrameRange, RejectsMalformed) {
  for (const char* bad : {"", "a", "1-", "-", "5-1", "1-10x0", "1-10x-2", "1,,2", "1-10,", "1.5", "1-2y3",
                          "1-99999999999", "0-2000000"}) {
    EXPECT_THROW(parse_frame_range(bad), UsageError) << "'" << bad << "'";
  }
}

TEST(FrameRangeText, RunsAndStepsAsFramesTakesThem) {
  EXPECT_EQ(format_frame_ranges({}), "");
  EXPECT_EQ(format_frame_ranges({7}), "7");
  EXPECT_EQ(format_frame_ranges({1001, 1002, 1003, 1004, 1005, 1006}), "1001-1006");
  EXPECT_EQ(format_frame_ranges({11, 3, 1, 2, 7, 9, 3}), "1-3,7-11x2");  // sorted, duplicates once
  EXPECT_EQ(format_frame_ranges({1, 3}), "1,3");                         // two apart are no run
  EXPECT_EQ(format_frame_ranges({-3, -2, -1, 5}), "-3--1,5");
}

TEST(FrameRangeText, ReadsBackAsTheSameFrames) {
  const std::vector<std::vector<long>> cases = {
      {1, 2, 4, 6, 8, 9, 10, 20}, {-5, -4, 0, 1, 2, 100, 200, 300, 301}, {1, 2}, {5, 10, 15, 16}, {-100000000, 100000000}};
  for (const auto& frames : cases) {
    std::vector<long> sorted = parse_frame_range(format_frame_ranges(frames, 100));
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, frames) << format_frame_ranges(frames, 100);
  }
}

TEST(FrameRangeText, ManyItemsStayOneShortLine) {
  std::vector<long> every_third;
  for (long f = 0; f < 300000; f += 3) every_third.push_back(f * (f % 2 ? 1 : 7));
  const std::string text = format_frame_ranges(every_third);
  EXPECT_LT(text.size(), 200u) << text;
  EXPECT_NE(text.find(",... (100000 frames in all)"), std::string::npos) << text;
}
