// libFuzzer target: the sequence planner (sequence/plan.h) and the sparse temporal smoothing.
// Input lines: input pattern, output pattern, --frames text ("" = none), options (c: the operator
// reads probe and sidecar; n: frames may lack inputs; digits: the smoothing radius), then the names
// found in the input folder, one per line. Checks invariants, not just crashes; the work must not
// grow with the numeric span of the frame numbers (libFuzzer's -timeout and -rss_limit_mb catch
// a planner that walks or allocates across a gap of 200 million frames).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/sequence/frame_pattern.h"
#include "cgtmo/sequence/plan.h"
#include "cgtmo/sequence/temporal.h"

namespace {

namespace fs = std::filesystem;
using namespace cgtmo::sequence;

void check(bool ok) {
  if (!ok) std::abort();
}

std::string normal(const std::string& p) { return fs::path(p).lexically_normal().string(); }

void check_plan(const SequenceRequest& r, const SequencePlan& p, long radius) {
  const std::set<std::string> names(r.folder_names.begin(), r.folder_names.end());
  check(!p.jobs.empty());
  check(std::is_sorted(p.frames_on_disk.begin(), p.frames_on_disk.end()));
  check(std::adjacent_find(p.frames_on_disk.begin(), p.frames_on_disk.end()) == p.frames_on_disk.end());
  const FramePattern in_p = FramePattern::parse(r.input_pattern);
  for (long f : p.frames_on_disk) {
    check(f >= -kMaxFrameNumber && f <= kMaxFrameNumber);
    check(names.count(fs::path(in_p.format(f)).filename().string()) == 1);
  }
  // The frames asked: --frames, or those found.
  std::set<long> asked;
  if (r.frames.empty()) {
    asked.insert(p.frames_on_disk.begin(), p.frames_on_disk.end());
  } else {
    const auto range = parse_frame_range(r.frames);
    asked.insert(range.begin(), range.end());
  }
  std::set<std::string> outputs, inputs;
  for (const auto& in : p.inputs) inputs.insert(normal(in));
  std::set<long> frames;
  for (const auto& j : p.jobs) {
    check(asked.count(j.frame) == 1);
    check(frames.insert(j.frame).second);
    check(outputs.insert(normal(j.output)).second);  // outputs distinct
    check(inputs.count(normal(j.input)) == 1);
    if (r.frames.empty()) check(names.count(fs::path(j.input).filename().string()) == 1);
  }
  check(p.inputs.size() == p.jobs.size() * (r.reads_companions ? 3 : 1));
  for (const auto& o : outputs) check(inputs.count(o) == 0);  // no output is any input
  for (long f : p.missing) check(frames.count(f) == 1);
  if (!r.allow_no_input && !r.frames.empty()) check(p.missing.size() < p.jobs.size());

  // Smoothing over the frames on disk near the jobs: each neighbour is on disk and within the
  // radius of a job; values 2^-3..2^3 smooth to within that range (a weighted geometric mean).
  std::vector<long> todo(frames.begin(), frames.end());
  const auto near = smoothing_neighbours(p.frames_on_disk, todo, radius);
  check(std::is_sorted(near.begin(), near.end()));
  check(std::adjacent_find(near.begin(), near.end()) == near.end());
  std::vector<double> values;
  for (long f : near) {
    check(std::binary_search(p.frames_on_disk.begin(), p.frames_on_disk.end(), f));
    const auto t = std::lower_bound(todo.begin(), todo.end(), f - radius);
    check(t != todo.end() && *t <= f + radius);
    values.push_back(f % 5 == 0 ? NAN : std::exp2(double(((f % 7) + 7) % 7 - 3)));
  }
  const auto smooth = smooth_in_stops_at(near, values, todo, radius / 3.0);
  check(smooth.size() == todo.size());
  for (double v : smooth) check(std::isnan(v) || (v >= 0.125 * (1 - 1e-12) && v <= 8 * (1 + 1e-12)));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  SequenceRequest r;
  std::string options;
  std::getline(in, r.input_pattern);
  std::getline(in, r.output_pattern);
  std::getline(in, r.frames);
  std::getline(in, options);
  for (std::string name; std::getline(in, name);) r.folder_names.push_back(name);
  r.reads_companions = options.find('c') != std::string::npos;
  r.allow_no_input = options.find('n') != std::string::npos;
  long radius = 0;
  for (char c : options)
    if (c >= '0' && c <= '9' && radius < 100000) radius = radius * 10 + (c - '0');
  try {
    // A million frames asked is allowed and linear in the count (fuzz_frame_pattern covers the
    // parser there); here such counts would only slow the search down.
    if (!r.frames.empty() && parse_frame_range(r.frames).size() > 10000) return 0;
    const SequencePlan p = plan_sequence(r);
    check_plan(r, p, radius);
  } catch (const cgtmo::UsageError&) {
  } catch (const cgtmo::DataError&) {
  }
  return 0;
}
