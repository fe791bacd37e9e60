#include "cgtmo/util/parallel.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/parallel.h>

#include <atomic>
#include <mutex>

#include "cgtmo/util/allocation.h"

namespace cgtmo {

namespace {
std::atomic<bool> g_set{false};
}  // namespace

void set_threads(int n) {
  if (n <= 0) n = process_allocation().cpus;
  OIIO::attribute("threads", n);
  g_set.store(true);
}

int thread_count() {
  // OpenImageIO's own default is the machine's core count: until set_threads is called, the pool
  // is sized to what this process is allotted instead.
  static std::once_flag once;
  std::call_once(once, [] {
    if (!g_set.load()) set_threads(0);
  });
  int n = 0;
  OIIO::getattribute("threads", n);
  return n > 0 ? n : process_allocation().cpus;
}

void parallel_rows(int64_t n, const std::function<void(int64_t, int64_t)>& f) {
  const int threads = thread_count();
  if (threads <= 1 || n < 2) {
    f(0, n);
    return;
  }
  // A few chunks per thread keeps the pool balanced without per-row scheduling cost.
  const int64_t chunks = std::min<int64_t>(n, int64_t(threads) * 4);
  // minitems 1: OIIO's default (1024 items per task) would run our few chunks on the caller alone.
  OIIO::parallel_for(
      int64_t(0), chunks,
      [&](int64_t c) {
        const int64_t b = n * c / chunks, e = n * (c + 1) / chunks;
        if (b < e) f(b, e);
      },
      OIIO::paropt(threads, OIIO::paropt::SplitDir::Y, 1));
}

}  // namespace cgtmo
