#pragma once
// `cgtmo apply` over a frame sequence: patterns, resumable runs, progress, signals, summary.
#include <string>

#include "cgtmo/pipeline/apply_file.h"

namespace cgtmo::cli {

struct SequenceOptions {
  std::string in_pattern, out_pattern;
  std::string frames;        // --frames; "" = every input frame found on disk
  bool force = false;        // redo frames whose output is up to date
  bool fail_fast = false;    // stop at the first failing frame
  bool dry_run = false;      // print "todo|skip FRAME IN OUT" per frame, change nothing
  bool list_frames = false;  // print the frame numbers, one per line
  bool quiet = false;
  int threads = 0;           // 0: all cores
  double max_memory_mb = 0;  // 0: half the machine's memory
};

// Returns the exit code: 0 all frames done or skipped, 1 some failed, 130 interrupted.
int run_apply_sequence(const pipeline::Applier& applier, const SequenceOptions& options);

}  // namespace cgtmo::cli
