#pragma once
// `cgtmo apply` over a frame sequence: patterns, resumable runs, progress, signals, summary.
#include <functional>
#include <map>
#include <string>

#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/sequence/batch.h"
#include "cgtmo/sequence/frame_statistics.h"
#include "cgtmo/sequence/provenance.h"

namespace cgtmo::cli {

struct SequenceOptions {
  std::string in_pattern, out_pattern;
  std::string frames;        // --frames; "" = every input frame found on disk
  bool force = false;        // redo frames whose output is up to date
  bool fail_fast = false;    // stop at the first failing frame
  bool dry_run = false;      // print "todo|skip|missing FRAME IN OUT [(why)]" per frame, change nothing
  bool list_frames = false;  // print the frame numbers, one per line
  bool quiet = false;
  bool json = false;         // --json: one JSON object on stdout at the end (implies quiet)
  int threads = 0;           // 0: the CPUs allotted (util/allocation.h)
  double max_memory_mb = 0;  // 0: half the memory allotted
  double temporal = 8;       // Gaussian sigma in frames for the statistics; 0: per-frame statistics
  bool reads_companions = false;  // scene operators: each frame also reads NAME.probe.exr and NAME.json
  // What each output records about how it was made; a frame whose output records otherwise is redone.
  sequence::ProvenanceRequest provenance;
};

// The files a frame reads, for its provenance: the beauty, and for scene operators the probe and
// sidecar beside it (or those given, when not empty).
std::vector<std::string> files_read_by(const std::string& input, bool reads_companions, const std::string& probe = "",
                                       const std::string& sidecar = "");

// Tone-maps one frame; `overrides` are parameter values (key=value) that replace per-frame
// statistics with their smoothed values; `hooks` carry the output's record and stage progress.
using FrameProcessor = std::function<void(const sequence::FrameJob&, const std::map<std::string, std::string>& overrides,
                                          const pipeline::FileHooks& hooks)>;

// Returns the exit code: 0 all frames done or skipped, 1 some failed, 130 interrupted.
// `plan` names the statistics to hold steady (sequence/frame_statistics.h).
int run_apply_sequence(const FrameProcessor& process, const sequence::StatisticsPlan& plan, const SequenceOptions& options);

}  // namespace cgtmo::cli
