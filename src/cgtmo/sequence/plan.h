#pragma once
// Which frames a sequence run does, with which input and output, decided without touching the
// file system (the caller lists the input folder), so that the CLI and a fuzzer share one planner.
// Every step's work grows with the number of frames and names, never with the numeric span of the
// frame numbers (frames -99999999 and 99999999 cost what frames 1 and 2 cost).
#include <string>
#include <vector>

#include "cgtmo/sequence/batch.h"
#include "cgtmo/sequence/frame_pattern.h"

namespace cgtmo::sequence {

struct SequenceRequest {
  std::string input_pattern, output_pattern;
  std::string frames;                     // --frames text; "" = every frame whose input is listed
  std::vector<std::string> folder_names;  // names of the entries in input_folder(input pattern)
  bool reads_companions = false;          // scene operators also read NAME.probe.exr and NAME.json
  bool allow_no_input = false;            // --dry-run: frames may not be rendered yet
};

struct SequencePlan {
  std::vector<FrameJob> jobs;           // --frames order, or ascending frames
  std::vector<long> frames_on_disk;     // ascending: frames whose input is among folder_names
  std::vector<std::string> inputs;      // every file a job reads (beauty, and companions)
  std::vector<std::string> warnings;    // one line each: names that look like frames but are ignored
  std::vector<long> missing;            // frames asked with --frames whose input is not listed
};

// Throws UsageError (bad pattern or --frames; two frames with one output; an output that is an
// input of any frame, compared as lexically normal paths) or DataError (no frame to do: none
// found, or, unless allow_no_input, none of the frames asked has an input).
SequencePlan plan_sequence(const SequenceRequest& request);

// The folder to list for `input`'s frames ("." for a bare name).
std::string input_folder(const FramePattern& input);

// The frames whose input is listed (ascending) among `folder_names`. A name shaped like a frame
// whose number is beyond +-kMaxFrameNumber adds a line to `warnings` and is ignored.
std::vector<long> frames_among(const FramePattern& input, const std::vector<std::string>& folder_names,
                               std::vector<std::string>* warnings);

// The frames of `frames_on_disk` (ascending) within `radius` of one of `todo`: the neighbours
// temporal smoothing measures. Ascending. Frames within +-kMaxFrameNumber, radius >= 0.
std::vector<long> smoothing_neighbours(const std::vector<long>& frames_on_disk, std::vector<long> todo, long radius);

}  // namespace cgtmo::sequence
