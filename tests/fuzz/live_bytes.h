#pragma once
// The bytes a fuzz target holds allocated at once, counted by sanitizer allocation hooks on every
// thread (OpenEXR decodes on threads of its own), so that a target can require a path to stay
// within its memory budget in total, not only per allocation (-malloc_limit_mb).
#include <sanitizer/allocator_interface.h>

#include <atomic>
#include <cstdint>

namespace cgtmo::fuzz {

inline std::atomic<std::int64_t> g_live_bytes{0}, g_peak_bytes{0};

inline void on_malloc(const volatile void*, std::size_t size) {
  const std::int64_t live = g_live_bytes.fetch_add(std::int64_t(size)) + std::int64_t(size);
  std::int64_t peak = g_peak_bytes.load();
  while (live > peak && !g_peak_bytes.compare_exchange_weak(peak, live)) {
  }
}

inline void on_free(const volatile void* p) {
  g_live_bytes.fetch_sub(std::int64_t(__sanitizer_get_allocated_size(const_cast<const void*>(p))));
}

// Call once, from LLVMFuzzerInitialize.
inline void count_live_bytes() { __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free); }

// The most bytes held at once beyond those held before, while `f` ran.
template <typename F>
std::int64_t peak_extra_bytes(F&& f) {
  const std::int64_t before = g_live_bytes.load();
  g_peak_bytes.store(before);
  f();
  return g_peak_bytes.load() - before;
}

}  // namespace cgtmo::fuzz
