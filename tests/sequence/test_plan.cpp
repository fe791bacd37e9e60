#include "cgtmo/sequence/plan.h"

#include <gtest/gtest.h>

#include "cgtmo/errors.h"

using namespace cgtmo;
using namespace cgtmo::sequence;

namespace {

SequenceRequest request(const std::string& in, const std::string& out, const std::string& frames,
                        std::vector<std::string> names) {
  SequenceRequest r;
  r.input_pattern = in;
  r.output_pattern = out;
  r.frames = frames;
  r.folder_names = std::move(names);
  return r;
}

std::vector<long> frames_of(const SequencePlan& p) {
  std::vector<long> f;
  for (const auto& j : p.jobs) f.push_back(j.frame);
  return f;
}

}  // namespace

TEST(SequencePlan, FindsTheFramesOfTheShotInTheFolderListing) {
  const auto p = plan_sequence(request("shots/a.####.exr", "out/a.####.png", "",
                                       {"a.0003.exr", "a.0001.exr", "a.0001.probe.exr", "a.01.exr", "b.0002.exr", "a.-0002.exr",
                                        "a.0000.exr", "a.-0000.exr", "a.00x1.exr", "a..exr", "a.-.exr"}));
  EXPECT_EQ(frames_of(p), (std::vector<long>{-2, 0, 1, 3}));
  EXPECT_EQ(p.jobs[2].input, "shots/a.0001.exr");
  EXPECT_EQ(p.jobs[2].output, "out/a.0001.png");
  EXPECT_TRUE(p.warnings.empty());
  EXPECT_TRUE(p.missing.empty());
}

TEST(SequencePlan, NoFrameFoundIsADataError) {
  EXPECT_THROW(plan_sequence(request("a.####.exr", "o.####.png", "", {"b.0001.exr"})), DataError);
}

TEST(SequencePlan, APatternWithOtherPaddingThanTheFilesSuggestsTheOneThatFindsThem) {
  const auto message = [](const std::string& in, std::vector<std::string> names) {
    try {
      plan_sequence(request(in, "o.####.png", "", std::move(names)));
    } catch (const DataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("shots/shot.#.exr", {"shot.0001.exr", "shot.0002.exr"}).find("4-digit numbers, as in 'shot.0001.exr': use 'shots/shot.####.exr'"),
            std::string::npos);
  EXPECT_NE(message("shot.%06d.exr", {"shot.0001.exr"}).find("use 'shot.####.exr'"), std::string::npos);
  // Nothing to suggest: another shot's files, or numbers that do not tell their padding.
  EXPECT_EQ(message("shot.#.exr", {"other.0001.exr"}).find("digit numbers"), std::string::npos);
  EXPECT_EQ(message("shot.##.exr", {"shot.1001.exr"}).find("digit numbers"), std::string::npos);
}

TEST(SequencePlan, FramesAskedWithoutAnyInputIsOneDataErrorWithRanges) {
  auto message = [](const SequenceRequest& r) {
    try {
      plan_sequence(r);
    } catch (const DataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(request("missing.####.exr", "out/o.####.png", "1-3", {})),
            "frames 1-3 of 'missing.####.exr' not found (on disk: none)");
  // A shot of frames 1001-1006 asked for 1-240: what is asked and what is there, as ranges.
  std::vector<std::string> shot;
  for (int f = 1001; f <= 1006; ++f) shot.push_back("a." + std::to_string(f) + ".exr");
  shot.push_back("a.1010.exr");
  EXPECT_EQ(message(request("r/a.####.exr", "o.####.png", "1-240", shot)),
            "frames 1-240 of 'r/a.####.exr' not found (on disk: 1001-1006,1010)");
  EXPECT_EQ(message(request("a.####.exr", "o.####.png", "7", shot)), "frame 7 of 'a.####.exr' not found (on disk: 1001-1006,1010)");
  // A name that would break the line is printed escaped.
  EXPECT_EQ(message(request("new\nline/a.####.exr", "o.####.png", "1", {})),
            "frame 1 of 'new\\nline/a.####.exr' not found (on disk: none)");
  EXPECT_EQ(message(request("new\nline/a.####.exr", "o.####.png", "1", {})).find('\n'), std::string::npos);
  // --dry-run may plan frames not rendered yet.
  auto r = request("missing.####.exr", "o.####.png", "1-3", {});
  r.allow_no_input = true;
  EXPECT_EQ(plan_sequence(r).missing, (std::vector<long>{1, 2, 3}));
}

TEST(SequencePlan, FramesAskedWithSomeInputsKeepTheMissingOnesToFail) {
  const auto p = plan_sequence(request("a.####.exr", "o.####.png", "4-6", {"a.0005.exr"}));
  EXPECT_EQ(frames_of(p), (std::vector<long>{4, 5, 6}));
  EXPECT_EQ(p.missing, (std::vector<long>{4, 6}));
}

TEST(SequencePlan, AnOutputThatIsAnotherFramesInputIsRefused) {
  // Frame 1's output a.-0001.exr is frame -1's input.
  try {
    plan_sequence(request("a.####.exr", "a.-####.exr", "-1-1", {"a.-0001.exr", "a.0000.exr", "a.0001.exr"}));
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("'a.-0001.exr' (frame 1) is an input of frame -1"), std::string::npos) << e.what();
  }
  // Spelled differently: ./ and a folder's ..
  EXPECT_THROW(plan_sequence(request("d/a.####.exr", "./d/../d/a.####.exr", "1", {"a.0001.exr"})), UsageError);
}

TEST(SequencePlan, ScenesProbeAndSidecarAreInputs) {
  auto r = request("a.####.exr", "a.####.probe.exr", "1-2", {"a.0001.exr", "a.0002.exr"});
  EXPECT_NO_THROW(plan_sequence(r));  // a per-pixel operator reads the beauty only
  r.reads_companions = true;
  EXPECT_THROW(plan_sequence(r), UsageError);
  r.output_pattern = "a.####.json";
  EXPECT_THROW(plan_sequence(r), UsageError);
  r.output_pattern = "out.####.exr";
  const auto p = plan_sequence(r);
  EXPECT_EQ(p.inputs, (std::vector<std::string>{"a.0001.exr", "a.0001.probe.exr", "a.0001.json", "a.0002.exr",
                                                 "a.0002.probe.exr", "a.0002.json"}));
}

TEST(SequencePlan, TwoFramesWithOneOutputAreRefused) {
  // The frame token in a folder that the path leaves again: every frame writes out/o.png.
  EXPECT_THROW(plan_sequence(request("a.####.exr", "out/#/../o.png", "1-2", {"a.0001.exr"})), UsageError);
  EXPECT_NO_THROW(plan_sequence(request("a.####.exr", "out/#/o.png", "1-2", {"a.0001.exr"})));
}

TEST(SequencePlan, NamesBeyondTheFrameRangeAreIgnoredWithAWarning) {
  const auto p = plan_sequence(request("shot.#.exr", "o.#.png", "",
                                       {"shot.99999999999999999999.exr", "shot.100000001.exr", "shot.-100000001.exr",
                                        "shot.100000000.exr", "shot.1.exr", "shot.0000000000000000000000002.exr"}));
  EXPECT_EQ(frames_of(p), (std::vector<long>{1, 100000000}));
  ASSERT_EQ(p.warnings.size(), 3u);
  EXPECT_NE(p.warnings[0].find("'shot.99999999999999999999.exr': frame number out of range"), std::string::npos)
      << p.warnings[0];
}

TEST(SequencePlan, FarApartFramesArePlannedWithoutWalkingTheGap) {
  const auto p = plan_sequence(request("a.#.exr", "o.#.png", "", {"a.-99999999.exr", "a.99999999.exr"}));
  EXPECT_EQ(frames_of(p), (std::vector<long>{-99999999, 99999999}));
}

TEST(SequencePlan, SmoothingNeighboursAreTheFramesOnDiskWithinTheRadius) {
  const std::vector<long> on_disk{-99999999, 1, 2, 3, 10, 30, 99999999};
  EXPECT_EQ(smoothing_neighbours(on_disk, {2}, 1), (std::vector<long>{1, 2, 3}));
  EXPECT_EQ(smoothing_neighbours(on_disk, {12, 2}, 2), (std::vector<long>{1, 2, 3, 10}));  // todo in any order
  EXPECT_EQ(smoothing_neighbours(on_disk, {-99999999, 99999999}, 24), (std::vector<long>{-99999999, 99999999}));
  EXPECT_EQ(smoothing_neighbours(on_disk, {20}, 5), std::vector<long>{});
  EXPECT_EQ(smoothing_neighbours({}, {20}, 5), std::vector<long>{});
  // Overlapping windows list each frame once.
  EXPECT_EQ(smoothing_neighbours(on_disk, {1, 2, 3}, 24), (std::vector<long>{1, 2, 3, 10}));
}

TEST(SequencePlan, InputFolderOfAPattern) {
  EXPECT_EQ(input_folder(FramePattern::parse("a.####.exr")), ".");
  EXPECT_EQ(input_folder(FramePattern::parse("/r/s/a.####.exr")), "/r/s");
}
