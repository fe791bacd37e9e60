#pragma once
// Runs one job per frame over a sequence: skips frames whose output is newer than the input,
// processes several frames at once, goes on past failures (or stops at the first), stops taking
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
  bool force = false;      // process frames whose output is up to date too
  bool fail_fast = false;  // stop taking frames after the first failure
  int concurrent_frames = 1;
  // Called (serialised) after each frame, with the outcomes so far.
  std::function<void(const FrameOutcome&, std::size_t finished, std::size_t total)> on_frame;
};

struct BatchSummary {
  std::vector<FrameOutcome> outcomes;  // in frame order
  std::size_t done = 0, skipped = 0, failed = 0, cancelled = 0;
  double seconds = 0.0;
};

// True when `output` exists and is not older than `input`.
bool output_up_to_date(const std::string& input, const std::string& output);

// `process` does one frame and throws (any std::exception) on failure.
BatchSummary run_batch(const std::vector<FrameJob>& jobs, const std::function<void(const FrameJob&)>& process,
                       const BatchOptions& options, const std::atomic<bool>* cancel);

}  // namespace cgtmo::sequence
