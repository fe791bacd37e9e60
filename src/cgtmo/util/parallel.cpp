#include "cgtmo/util/parallel.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/parallel.h>

#include <thread>

namespace cgtmo {

void set_threads(int n) {
  if (n <= 0) n = int(std::thread::hardware_concurrency());
  OIIO::attribute("threads", n);
}

int thread_count() {
  int n = 0;
  OIIO::getattribute("threads", n);
  return n > 0 ? n : int(std::thread::hardware_concurrency());
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
