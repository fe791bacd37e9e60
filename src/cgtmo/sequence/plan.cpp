#include "cgtmo/sequence/plan.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "cgtmo/errors.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/util/text.h"

namespace cgtmo::sequence {

namespace fs = std::filesystem;

namespace {

// The frame token is in the file name (not in a folder name), so listing one folder finds frames.
bool listable(const FramePattern& p) { return p.suffix().find('/') == std::string::npos; }

std::string file_name_part(const FramePattern& p) { return fs::path(p.prefix()).filename().string(); }

std::string normal(const std::string& path) { return fs::path(path).lexically_normal().string(); }

// The text between the pattern's file-name prefix and its suffix in `name` ("0012" of
// "shot.0012.exr" for shot.####.exr), or "" when `name` is not named like the pattern.
std::string number_part(const std::string& name, const std::string& name_prefix, const std::string& suffix) {
  const std::size_t fixed = name_prefix.size() + suffix.size();
  if (name.size() <= fixed || name.compare(0, name_prefix.size(), name_prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return "";
  return name.substr(name_prefix.size(), name.size() - fixed);
}

// When files named like the pattern exist but with another zero padding (`shot.#.exr` beside
// shot.0001.exr), the pattern that finds them: " (the files on disk have 4-digit numbers, as in
// 'shot.0001.exr': use 'shot.####.exr')". Else "".
std::string padding_hint(const FramePattern& p, const std::vector<std::string>& names) {
  if (!listable(p)) return "";
  const std::string name_prefix = file_name_part(p), &suffix = p.suffix();
  for (const auto& n : names) {
    const std::string number = number_part(n, name_prefix, suffix);
    if (number.empty() || number.size() > 12 || number[0] != '0' || number.find_first_not_of("0123456789") != std::string::npos ||
        int(number.size()) == p.width())
      continue;  // only a zero-padded number tells its width
    return " (the files on disk have " + std::to_string(number.size()) + "-digit numbers, as in '" + n + "': use '" +
           p.prefix() + std::string(number.size(), '#') + suffix + "')";
  }
  return "";
}

}  // namespace

std::string input_folder(const FramePattern& input) {
  const fs::path dir = fs::path(input.prefix()).parent_path();
  return dir.empty() ? "." : dir.string();
}

std::vector<long> frames_among(const FramePattern& p, const std::vector<std::string>& names,
                               std::vector<std::string>* warnings) {
  std::vector<long> found;
  if (!listable(p)) return found;
  const std::string name_prefix = file_name_part(p), &suffix = p.suffix();
  for (const auto& n : names) {
    const std::string number = number_part(n, name_prefix, suffix);
    if (number.empty()) continue;
    const bool negative = number[0] == '-';
    const std::size_t first_digit = negative ? 1 : 0;
    if (number.size() == first_digit || int(number.size()) < p.width() ||
        number.find_first_not_of("0123456789", first_digit) != std::string::npos)
      continue;
    // Digits after the leading zeros: more than 9 is beyond kMaxFrameNumber (and maybe beyond long).
    const std::size_t significant = std::min(number.find_first_not_of('0', first_digit), number.size());
    long f = 0;
    if (significant < number.size() && number.size() - significant <= 9) f = std::stol(number.substr(significant));
    if (number.size() - significant > 9 || f > kMaxFrameNumber) {
      if (warnings)
        warnings->push_back("ignoring '" + n + "': frame number out of range (at most " + std::to_string(kMaxFrameNumber) +
                            " either side of 0)");
      continue;
    }
    if (negative) f = -f;
    // Only the name this frame formats to counts (padding and sign exactly as the pattern writes them).
    if (fs::path(p.format(f)).filename().string() == n) found.push_back(f);
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

SequencePlan plan_sequence(const SequenceRequest& r) {
  const FramePattern in_p = FramePattern::parse(r.input_pattern);
  if (!FramePattern::is_pattern(r.output_pattern))
    throw UsageError("output '" + r.output_pattern + "' needs a frame token (####, @@@@ or %04d) when the input is a sequence");
  const FramePattern out_p = FramePattern::parse(r.output_pattern);
  SequencePlan plan;
  plan.frames_on_disk = frames_among(in_p, r.folder_names, &plan.warnings);
  const std::vector<long> frames = r.frames.empty() ? plan.frames_on_disk : parse_frame_range(r.frames);
  if (frames.empty())
    throw DataError("no input frames match '" + r.input_pattern + "'" + padding_hint(in_p, r.folder_names));

  // Every file the run reads, by its lexically normal path, with the frame that reads it.
  std::unordered_map<std::string, long> read_by;
  std::unordered_set<std::string> outputs;
  plan.jobs.reserve(frames.size());
  read_by.reserve(frames.size() * (r.reads_companions ? 3 : 1));
  outputs.reserve(frames.size());
  for (long f : frames) {
    FrameJob j{f, in_p.format(f), out_p.format(f)};
    if (!outputs.insert(normal(j.output)).second) throw UsageError("two frames write the same output '" + j.output + "'");
    plan.inputs.push_back(j.input);
    if (r.reads_companions) {
      plan.inputs.push_back(io::probe_path_for(j.input));
      plan.inputs.push_back(io::sidecar_path_for(j.input));
    }
    plan.jobs.push_back(std::move(j));
  }
  for (std::size_t i = 0; i < plan.inputs.size(); ++i)
    read_by.emplace(normal(plan.inputs[i]), plan.jobs[i / (r.reads_companions ? 3 : 1)].frame);
  for (const auto& j : plan.jobs) {
    const auto it = read_by.find(normal(j.output));
    if (it != read_by.end())
      throw UsageError("output '" + j.output + "' (frame " + std::to_string(j.frame) + ") is an input of frame " +
                       std::to_string(it->second) + ": refusing to overwrite it");
  }

  // Frames asked for whose input is not there: they fail one by one, unless none has an input.
  if (!r.frames.empty() && listable(in_p)) {
    const std::unordered_set<long> on_disk(plan.frames_on_disk.begin(), plan.frames_on_disk.end());
    for (const auto& j : plan.jobs)
      if (!on_disk.count(j.frame)) plan.missing.push_back(j.frame);
    // One line, the frames as ranges (cgtmo-slurm prints it as it is, before queueing anything).
    if (plan.missing.size() == plan.jobs.size() && !r.allow_no_input) {
      const std::string on_disk = format_frame_ranges(plan.frames_on_disk);
      throw DataError(std::string(plan.jobs.size() > 1 ? "frames " : "frame ") + format_frame_ranges(plan.missing) +
                      " of '" + printable(r.input_pattern) + "' not found (on disk: " + (on_disk.empty() ? "none" : on_disk) +
                      ")");
    }
  }
  return plan;
}

std::vector<long> smoothing_neighbours(const std::vector<long>& on_disk, std::vector<long> todo, long radius) {
  std::vector<long> out;
  if (on_disk.empty() || todo.empty() || radius < 0) return out;
  radius = std::min(radius, 2 * kMaxFrameNumber + 1);  // wider covers every frame anyway; no overflow
  std::sort(todo.begin(), todo.end());
  // Windows [t - radius, t + radius] of the sorted frames to do, merged as they overlap: each frame on
  // disk is looked at once, whatever the gaps between frame numbers.
  auto from = on_disk.begin();
  for (std::size_t i = 0; i < todo.size();) {
    const long lo = todo[i] - radius;
    long hi = todo[i] + radius;
    for (++i; i < todo.size() && todo[i] - radius <= hi + 1; ++i) hi = todo[i] + radius;
    from = std::lower_bound(from, on_disk.end(), lo);
    for (; from != on_disk.end() && *from <= hi; ++from) out.push_back(*from);
  }
  return out;
}

}  // namespace cgtmo::sequence
