#pragma once
// One thread pool for the whole library: OpenImageIO's. Work is split over rows.
#include <cstdint>
#include <functional>

namespace cgtmo {

// Sets the pool size (0: the CPUs this process is allotted, util/allocation.h). Also what OIIO
// uses for its own I/O work. Until it is called, thread_count() sets the allotted size itself.
void set_threads(int n);
int thread_count();

// Calls f(begin, end) over disjoint chunks of [0, n).
void parallel_rows(int64_t n, const std::function<void(int64_t, int64_t)>& f);

}  // namespace cgtmo
