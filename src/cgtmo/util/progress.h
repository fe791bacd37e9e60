#pragma once
// Stages of one long job (an 8K scene frame runs tens of seconds), reported as each starts, so a
// terminal can show where the frame is and a farm log gets a line per stage.
#include <functional>

namespace cgtmo {

struct Stage {
  const char* name;  // "read", "statistics", "filter", "tone-map", "encode", "write"
  int index;         // 1-based
  int count;         // stages of this job
};
using StageCallback = std::function<void(const Stage&)>;

}  // namespace cgtmo
