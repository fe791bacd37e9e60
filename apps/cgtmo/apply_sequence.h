#pragma once
// `cgtmo apply` over a frame sequence: patterns, resumable runs, progress, signals, summary.
#include <functional>
#include <map>
#include <string>

#include "cgtmo/sequence/batch.h"
#include "cgtmo/sequence/frame_statistics.h"

namespace cgtmo::cli {

struct SequenceOptions {
  std::string in_pattern, out_pattern;
  std::string frames;        // --frames; "" = every input frame found on disk
  bool force = false;        // redo frames whose output is up to date
  bool fail_fast = false;    // stop at the first failing frame
  bool dry_run = false;      // print "todo|skip FRAME IN OUT" per frame, change nothing
  bool list_frames = false;  // print the frame numbers, one per line
  bool quiet = false;
  int threads = 0;           // 0: the CPUs allotted (util/allocation.h)
  double max_memory_mb = 0;  // 0: half the memory allotted
  double temporal = 8;       // Gaussian sigma in frames for the statistics; 0: per-frame statistics
  bool reads_companions = false;  // scene operators: each frame also reads NAME.probe.exr and NAME.json
};

// Tone-maps one frame; `overrides` are parameter values (key=value) that replace per-frame
// statistics with their smoothed values.
using FrameProcessor = std::function<void(const sequence::FrameJob&, const std::map<std::string, std::string>& overrides)>;

// Returns the exit code: 0 all frames done or skipped, 1 some failed, 130 interrupted.
// `plan` names the statistics to hold steady (sequence/frame_statistics.h).
int run_apply_sequence(const FrameProcessor& process, const sequence::StatisticsPlan& plan, const SequenceOptions& options);

}  // namespace cgtmo::cli
