#include "cgtmo/util/parallel.h"

#include <OpenImageIO/parallel.h>
#include <OpenImageIO/thread.h>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/util/allocation.h"

namespace cgtmo {

namespace {

std::atomic<int> g_threads{0};  // 0: not set yet

// Pools of our own, not OIIO's default one, whose size is the host's "threads" attribute. One
// pool per thread count in use, so that a call never runs on more threads than asked: OIIO's
// parallel_for hands chunks to every idle worker of the pool it is given, and a pool must not be
// resized while work runs on it. A host that changes the count often (an add-on's threads slider)
// must not collect idle pools: making a pool drops every other one that no call is using.
std::mutex g_pools_mutex;
std::map<int, std::shared_ptr<OIIO::thread_pool>> g_pools;

std::shared_ptr<OIIO::thread_pool> pool_for(int threads) {
  std::lock_guard<std::mutex> lock(g_pools_mutex);
  auto& pool = g_pools[threads];
  if (!pool) {
    // Only this map can hand a pool out, under this lock: a count of 1 means no call holds it.
    for (auto it = g_pools.begin(); it != g_pools.end();)
      it = it->second && it->second.use_count() == 1 ? g_pools.erase(it) : std::next(it);
    pool = std::make_shared<OIIO::thread_pool>(threads - 1);  // the caller works too
  }
  return pool;
}

}  // namespace

void set_threads(long long n) {
  if (n < 0 || n > kMaxThreads)
    throw UsageError("threads: " + std::to_string(n) + " is not in [0, " + std::to_string(kMaxThreads) +
                     "] (0: the CPUs this process is allotted)");
  g_threads.store(n == 0 ? std::max(process_allocation().cpus, 1) : int(n));
}

int thread_count() {
  const int n = g_threads.load();
  return n > 0 ? n : std::max(process_allocation().cpus, 1);
}

void parallel_rows(int64_t n, const std::function<void(int64_t, int64_t)>& f) {
  const int threads = thread_count();
  if (threads <= 1 || n < 2) {
    f(0, n);
    return;
  }
  const std::shared_ptr<OIIO::thread_pool> pool = pool_for(threads);
  // A few chunks per thread keeps the pool balanced without per-row scheduling cost.
  const int64_t chunks = std::min<int64_t>(n, int64_t(threads) * 4);
  // minitems 1: OIIO's default (1024 items per task) would run our few chunks on the caller alone.
  // OIIOpool: never TBB's global arena, whose size the host may also have set.
  OIIO::parallel_for(
      int64_t(0), chunks,
      [&](int64_t c) {
        const int64_t b = n * c / chunks, e = n * (c + 1) / chunks;
        if (b < e) f(b, e);
      },
      OIIO::paropt(threads, OIIO::paropt::SplitDir::Y, 1).pool(pool.get()).strategy(OIIO::paropt::ParStrategy::OIIOpool));
}

}  // namespace cgtmo
