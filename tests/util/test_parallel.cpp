// util/parallel: the pool really runs chunks at once. OIIO's parallel_for runs fewer items than
// its `minitems` (1024 by default) on the caller alone, which once made every "2 threads" run of
// the library serial; this test fails in that case instead of waiting forever.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "cgtmo/errors.h"
#include "cgtmo/util/parallel.h"

namespace cgtmo {
namespace {

TEST(ParallelRows, TwoThreadsRunTwoChunksAtOnce) {
  set_threads(2);
  std::atomic<int> started{0};
  std::atomic<bool> met{false};
  parallel_rows(8, [&](int64_t, int64_t) {
    // The first chunk waits (up to 60 s, only reached when it fails) until a second one has started: it can only see that
    // while it is still running if the two run at once.
    const int mine = ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (started.load() < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    if (mine == 1 && started.load() >= 2) met = true;
  });
  set_threads(0);
  EXPECT_TRUE(met.load()) << "parallel_rows ran its chunks one after another with 2 threads";
}

TEST(ParallelRows, CoversEveryRowOnceWithOneAndManyThreads) {
  for (int threads : {1, 2, 3}) {
    set_threads(threads);
    std::vector<std::atomic<int>> hits(1001);
    parallel_rows(1001, [&](int64_t b, int64_t e) {
      for (int64_t i = b; i < e; ++i) ++hits[std::size_t(i)];
    });
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), 1) << "row " << i << ", " << threads << " threads";
  }
  set_threads(0);
}

TEST(ParallelRows, ThreadCountFollowsSetThreads) {
  set_threads(3);
  EXPECT_EQ(thread_count(), 3);
  set_threads(1);
  EXPECT_EQ(thread_count(), 1);
  set_threads(0);
  EXPECT_GE(thread_count(), 1);
}

// One range for every face (the CLI's --threads, the Python module): a count outside it is a
// UsageError and leaves the count as it was (40,000 made a pool that crashed a Python host).
TEST(ParallelRows, SetThreadsTakesZeroToMaxThreadsOnly) {
  set_threads(2);
  for (long long bad : {-1LL, -2147483648LL, kMaxThreads + 1LL, 40000LL, 1LL << 40}) {
    try {
      set_threads(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()), "threads: " + std::to_string(bad) + " is not in [0, 1024] (0: the CPUs this process is allotted)");
    }
    EXPECT_EQ(thread_count(), 2);
  }
  set_threads(kMaxThreads);
  EXPECT_EQ(thread_count(), kMaxThreads);
  set_threads(0);
}

// The library's count is its own: a host's OpenImageIO "threads" setting survives set_threads and
// parallel work (the Python module's side of this is tests/plugins/test_host_threads.py).
TEST(ParallelRows, LeavesOpenImageIOsThreadsAttributeAlone) {
  int host = 0;
  OIIO::getattribute("threads", host);
  OIIO::attribute("threads", 5);
  for (int threads : {2, 3, 0}) {
    set_threads(threads);
    std::atomic<int> rows{0};
    parallel_rows(100, [&](int64_t b, int64_t e) { rows += int(e - b); });
    EXPECT_EQ(rows.load(), 100);
    int now = 0;
    OIIO::getattribute("threads", now);
    EXPECT_EQ(now, 5) << "set_threads(" << threads << ") changed OpenImageIO's process-wide thread count";
  }
  OIIO::attribute("threads", host);
}

// The threads this process has now (Linux: one entry per thread in /proc/self/task).
std::size_t process_threads() {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/task")) n += e.is_directory();
  return n;
}

// A host that moves its threads slider through many counts keeps one pool, not one per count
// (2 to 17 threads would otherwise leave 1 + 2 + ... + 16 = 136 idle workers behind).
TEST(ParallelRows, ChangingTheCountDoesNotCollectIdlePools) {
  if (!std::filesystem::exists("/proc/self/task")) GTEST_SKIP() << "no /proc/self/task to count threads";
  auto run = [](int threads) {
    set_threads(threads);
    std::atomic<int> rows{0};
    parallel_rows(1000, [&](int64_t b, int64_t e) { rows += int(e - b); });
    return rows.load();
  };
  ASSERT_EQ(run(2), 1000);
  const std::size_t before = process_threads();  // with the 2-thread pool's one worker
  for (int threads = 3; threads <= 17; ++threads) ASSERT_EQ(run(threads), 1000) << threads << " threads";
  const std::size_t after = process_threads();
  std::printf("process threads: %zu with the 2-thread pool, %zu after counts 3 to 17\n", before, after);
  set_threads(0);
  EXPECT_LE(after, before + 15) << "threads before " << before << ", after " << after;
}

}  // namespace
}  // namespace cgtmo
