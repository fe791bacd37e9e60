#pragma once
// Frame-sequence file names and frame ranges, as VFX tools write them.
//   Padding: a run of N '#' or N '@' is the frame number zero-padded to N digits (Nuke, RV);
//   printf style %d / %0Nd too. One frame token per name.
//   Ranges (--frames): "1-240", "1-240x2" (every 2nd), "7", and comma lists "1-10,20,30-40x5".
#include <string>
#include <vector>

namespace cgtmo::sequence {

class FramePattern {
 public:
  // Throws UsageError when `text` has no frame token, several, or a malformed one.
  static FramePattern parse(const std::string& text);
  // True when `text` holds a frame token (so callers can tell a sequence from a single file).
  static bool is_pattern(const std::string& text);

  std::string format(long frame) const;  // the file name of one frame
  const std::string& text() const { return text_; }
  int width() const { return width_; }
  // The text before and after the frame token (the prefix holds the folder, if any).
  const std::string& prefix() const { return prefix_; }
  const std::string& suffix() const { return suffix_; }

 private:
  std::string text_, prefix_, suffix_;
  int width_ = 1;
};

// Parses a --frames value into the frame numbers in order (duplicates removed, order kept).
// Throws UsageError naming the bad part. At most kMaxFrames frames, each within +-kMaxFrameNumber.
std::vector<long> parse_frame_range(const std::string& text);
inline constexpr std::size_t kMaxFrames = 1000000;

// `frames` (any order, duplicates allowed) written as --frames takes them, ascending: runs of
// consecutive frames as "1-240", evenly spaced runs of three or more as "1-9x2", others alone:
// {1, 2, 3, 7, 9, 11} -> "1-3,7-11x2", and parse_frame_range reads it back. At most `max_items`
// items: the rest as ",... (N frames in all)", so a message stays one short line. "" for none.
std::string format_frame_ranges(std::vector<long> frames, std::size_t max_items = 8);
inline constexpr long kMaxFrameNumber = 100000000;

}  // namespace cgtmo::sequence
