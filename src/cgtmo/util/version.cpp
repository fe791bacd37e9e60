#include "cgtmo/util/version.h"

#ifndef CGTMO_VERSION
#error "CGTMO_VERSION is defined by src/cgtmo/CMakeLists.txt"
#endif

namespace cgtmo {
const char* version() { return CGTMO_VERSION; }
}  // namespace cgtmo
