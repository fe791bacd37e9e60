#pragma once
// One thread pool for the whole library: OpenImageIO's. Work is split over rows.
#include <cstdint>
#include <functional>

namespace cgtmo {

// Sets the pool size (0: all cores). Also what OIIO uses for its own I/O work.
void set_threads(int n);
int thread_count();

// Calls f(begin, end) over disjoint chunks of [0, n).
void parallel_rows(int64_t n, const std::function<void(int64_t, int64_t)>& f);

}  // namespace cgtmo
