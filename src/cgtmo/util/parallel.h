#pragma once
// The library's own thread pool. Work is split over rows.
//
// The library never sets OpenImageIO's process-wide "threads" attribute: loaded into a host
// (Blender, Nuke, a Python session) that setting belongs to the host. The count here is the
// library's alone: parallel_rows runs on a pool of its own, and the library's reads and writes
// pass it to OpenImageIO per file (ImageInput/ImageOutput::threads).
#include <cstdint>
#include <functional>

namespace cgtmo {

// The thread counts set_threads takes, for every face (the CLI's --threads, the Python module):
// 0 (the CPUs this process is allotted) to kMaxThreads. A pool of tens of thousands of threads
// exhausts the process (40,000 crashed a Python host).
inline constexpr int kMaxThreads = 1024;

// Sets the library's thread count for every later call (0: the CPUs this process is allotted,
// util/allocation.h). Throws UsageError outside [0, kMaxThreads]. Call it between calls, not
// while one runs on another thread.
void set_threads(long long n);
// The library's thread count: what set_threads gave, else the allotted CPUs.
int thread_count();

// Calls f(begin, end) over disjoint chunks of [0, n).
void parallel_rows(int64_t n, const std::function<void(int64_t, int64_t)>& f);

}  // namespace cgtmo
