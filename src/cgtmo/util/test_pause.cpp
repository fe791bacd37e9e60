#include "cgtmo/util/test_pause.h"

#include <signal.h>

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace cgtmo {

void test_pause_point(const char* name) {
  static const char* const at = std::getenv("CGTMO_TEST_PAUSE_AT");
  static std::atomic<bool> paused{false};
  if (at && std::strcmp(at, name) == 0 && !paused.exchange(true)) ::raise(SIGSTOP);
}

}  // namespace cgtmo
