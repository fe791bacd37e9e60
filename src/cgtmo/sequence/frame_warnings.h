#pragma once
// The warnings of a sequence's frames, grouped: a shot of 240 frames without probes warns once,
// "frames 1001-1240: no adaptation probe (...)", not 240 times and not never. A message names
// its frame's files; those names are written back as the pattern, so the same warning on
// different frames is the same text.
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "cgtmo/sequence/frame_pattern.h"

namespace cgtmo::sequence {

class FrameWarnings {
 public:
  explicit FrameWarnings(FramePattern input) : input_(std::move(input)) {}

  // Thread-safe: frames warn from the workers that run them.
  void add(long frame, const std::string& message);

  struct Group {
    std::vector<long> frames;  // sorted, each once
    std::string message;       // with the frame's file names written as the pattern
  };
  // In the order each message first came.
  std::vector<Group> groups() const;
  // One line per group, the frames as --frames takes them (format_frame_ranges): "frame 4:
  // MESSAGE" or "frames 1-12,20: MESSAGE".
  std::vector<std::string> lines() const;

 private:
  std::string general(long frame, const std::string& message) const;
  FramePattern input_;
  mutable std::mutex mutex_;
  std::vector<Group> groups_;
  std::unordered_map<std::string, std::size_t> index_;  // message -> its group
};

}  // namespace cgtmo::sequence
