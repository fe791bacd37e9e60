// libFuzzer target: the frame-pattern and frame-range parsers (sequence/frame_pattern.h).
// Input: "<pattern>\n<range>". Checks invariants, not just crashes.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/sequence/frame_pattern.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  const auto nl = in.find('\n');
  const std::string pattern = in.substr(0, nl);
  const std::string range = nl == std::string::npos ? "" : in.substr(nl + 1);
  using namespace cgtmo::sequence;
  try {
    const FramePattern p = FramePattern::parse(pattern);
    if (!FramePattern::is_pattern(pattern)) std::abort();
    for (long f : {0L, 1L, 42L, -7L, 99999999L}) {
      const std::string name = p.format(f);
      if (name.size() + 14 < pattern.size()) std::abort();  // prefix and suffix survive (a token is at most 14 chars)
    }
  } catch (const cgtmo::UsageError&) {
  }
  try {
    const auto frames = parse_frame_range(range);
    if (frames.empty() || frames.size() > kMaxFrames) std::abort();
  } catch (const cgtmo::UsageError&) {
  }
  return 0;
}
