#pragma once
// Runs one job per frame over a sequence: skips frames the caller says are up to date
// (sequence/provenance.h decides that from each output's record), processes several frames at once, goes on past failures (or stops at the first), stops taking
// new frames when cancelled, and reports each frame as it ends.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace cgtmo::sequence {

struct FrameJob {
  long frame = 0;
  std::string input, output;
};

enum class FrameStatus { Done, Skipped, Failed, Cancelled };
const char* status_name(FrameStatus s);

struct FrameOutcome {
  FrameJob job;
  FrameStatus status = FrameStatus::Done;
  std::string error;  // for Failed
  double ms = 0.0;
};

struct BatchOptions {
  bool fail_fast = false;  // stop taking frames after the first failure
  int concurrent_frames = 1;
  // True for a frame to skip (its output is up to date); unset: every frame is processed.
  std::function<bool(const FrameJob&)> up_to_date;
  // Called (serialised) after each frame that was skipped, done or failed. `finished` counts those
  // frames only: frames not started after a cancel are not counted, so the count never claims them.
  std::function<void(const FrameOutcome&, std::size_t finished, std::size_t total)> on_frame;
};

struct BatchSummary {
  std::vector<FrameOutcome> outcomes;  // in frame order
  std::size_t done = 0, skipped = 0, failed = 0, cancelled = 0;
  double seconds = 0.0;
};

// `process` does one frame and throws (any std::exception) on failure.
BatchSummary run_batch(const std::vector<FrameJob>& jobs, const std::function<void(const FrameJob&)>& process,
                       const BatchOptions& options, const std::atomic<bool>* cancel);

}  // namespace cgtmo::sequence
