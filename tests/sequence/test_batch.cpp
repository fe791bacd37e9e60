#include "cgtmo/sequence/batch.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace fs = std::filesystem;
using namespace cgtmo::sequence;

namespace {

struct TempDir : cgtmo::test::CaseDir {
  TempDir() : CaseDir("cgtmo_batch") {}
};

void touch(const fs::path& p) { std::ofstream(p) << "x"; }

std::vector<FrameJob> jobs_in(const fs::path& dir, int n) {
  std::vector<FrameJob> jobs;
  for (int i = 1; i <= n; ++i) {
    const auto in = dir / ("in." + std::to_string(i));
    touch(in);
    jobs.push_back({i, in.string(), (dir / ("out." + std::to_string(i))).string()});
  }
  return jobs;
}

}  // namespace

TEST(Batch, ProcessesEveryFrameAndReportsInOrder) {
  TempDir d;
  const auto jobs = jobs_in(d.path, 9);
  std::mutex m;
  std::set<long> seen;
  BatchOptions opt;
  opt.concurrent_frames = 3;
  std::size_t reported = 0;
  opt.on_frame = [&](const FrameOutcome&, std::size_t finished, std::size_t total) {
    EXPECT_EQ(total, 9u);
    EXPECT_EQ(finished, ++reported);
  };
  const auto sum = run_batch(jobs, [&](const FrameJob& j) {
    std::lock_guard<std::mutex> l(m);
    seen.insert(j.frame);
    touch(j.output);
  }, opt, nullptr);
  EXPECT_EQ(sum.done, 9u);
  EXPECT_EQ(seen.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(sum.outcomes[i].job.frame, long(i + 1));
}

TEST(Batch, SkipsWhatTheCallerCallsUpToDate) {
  TempDir d;
  const auto jobs = jobs_in(d.path, 4);
  int calls = 0;
  auto count = [&](const FrameJob& j) { ++calls; touch(j.output); };
  BatchOptions opt;
  opt.up_to_date = [](const FrameJob& j) { return j.frame == 2; };
  auto sum = run_batch(jobs, count, opt, nullptr);
  EXPECT_EQ(sum.skipped, 1u);
  EXPECT_EQ(sum.done, 3u);
  EXPECT_EQ(sum.outcomes[1].status, FrameStatus::Skipped);
  // Without the predicate (what --force gives) every frame is processed.
  sum = run_batch(jobs, count, BatchOptions{}, nullptr);
  EXPECT_EQ(sum.done, 4u);
  EXPECT_EQ(calls, 7);
}

TEST(Batch, FailuresAreReportedAndTheRestGoOn) {
  TempDir d;
  const auto jobs = jobs_in(d.path, 5);
  auto sum = run_batch(jobs, [](const FrameJob& j) {
    if (j.frame == 2 || j.frame == 4) throw std::runtime_error("bad frame " + std::to_string(j.frame));
  }, BatchOptions{}, nullptr);
  EXPECT_EQ(sum.failed, 2u);
  EXPECT_EQ(sum.done, 3u);
  EXPECT_EQ(sum.outcomes[3].error, "bad frame 4");
}

TEST(Batch, FailFastStopsTakingFrames) {
  TempDir d;
  const auto jobs = jobs_in(d.path, 6);
  BatchOptions opt;
  opt.fail_fast = true;
  auto sum = run_batch(jobs, [](const FrameJob& j) {
    if (j.frame == 2) throw std::runtime_error("boom");
  }, opt, nullptr);
  EXPECT_EQ(sum.done, 1u);
  EXPECT_EQ(sum.failed, 1u);
  EXPECT_EQ(sum.cancelled, 4u);
}

TEST(Batch, CancellationLeavesTheRestUntouched) {
  TempDir d;
  const auto jobs = jobs_in(d.path, 6);
  std::atomic<bool> cancel{false};
  auto sum = run_batch(jobs, [&](const FrameJob& j) {
    if (j.frame == 3) cancel.store(true);
  }, BatchOptions{}, &cancel);
  EXPECT_EQ(sum.done, 3u);
  EXPECT_EQ(sum.cancelled, 3u);
}

TEST(Batch, TheCounterNeverCountsFramesNotStarted) {
  // After a cancel the frames in flight still report: their count is of frames that ran, never
  // "[6/6]" for a run that stopped after three.
  TempDir d;
  const auto jobs = jobs_in(d.path, 6);
  std::atomic<bool> cancel{false};
  BatchOptions opt;
  std::vector<std::size_t> counts;
  opt.on_frame = [&](const FrameOutcome& o, std::size_t finished, std::size_t total) {
    EXPECT_EQ(total, 6u);
    EXPECT_NE(o.status, FrameStatus::Cancelled);
    counts.push_back(finished);
  };
  run_batch(jobs, [&](const FrameJob& j) {
    if (j.frame == 3) cancel.store(true);
  }, opt, &cancel);
  EXPECT_EQ(counts, (std::vector<std::size_t>{1, 2, 3}));
}
