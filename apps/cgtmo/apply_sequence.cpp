#include "apply_sequence.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <iomanip>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>
#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/sequence/batch.h"
#include "cgtmo/sequence/frame_pattern.h"
#include "cgtmo/sequence/plan.h"
#include "cgtmo/sequence/frame_warnings.h"
#include "cgtmo/sequence/temporal.h"
#include "cgtmo/util/allocation.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/text.h"
#include "stage_progress.h"

namespace cgtmo::cli {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> g_cancel{false};
std::atomic<int> g_signals{0};

extern "C" void on_signal(int) {
  if (g_signals.fetch_add(1) == 0) {
    g_cancel.store(true);
    const char msg[] = "\ncgtmo apply: interrupted: finishing the frames in flight (again to stop at once)\n";
    ssize_t ignored = ::write(2, msg, sizeof msg - 1);
    (void)ignored;
    return;
  }
  io::unlink_registered_temps_signal_safe();  // nothing partial stays behind
  ::_exit(130);
}

// The names in the input pattern's folder, for the planner (an unreadable folder lists nothing).
std::vector<std::string> folder_names(const sequence::FramePattern& input) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(sequence::input_folder(input), ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  return names;
}

std::string human_time(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char b[32];
  const long t = long(s + 0.5);
  std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  return b;
}

// The readers' budget: half of the memory this process is allotted (io/input_file.h).
double default_memory_mb() { return double(io::default_memory_budget()) / (1024.0 * 1024.0); }

std::string mb_text(double mb) {
  char b[32];
  std::snprintf(b, sizeof b, mb < 10 ? "%.1f MB" : "%.0f MB", mb);
  return b;
}

// "affinity mask" -> "the affinity mask"; environment variables go without the article.
std::string the(const std::string& source) { return source.rfind("SLURM_", 0) == 0 ? source : "the " + source; }

// Smoothed statistics for the frames to do: measured on every input of the shot that lies within
// 3 sigma of one of them (so a chunk of a farm run sees the same neighbours as a whole run).
std::map<long, std::map<std::string, std::string>> smoothed_statistics(
    const sequence::StatisticsPlan& plan, const sequence::FramePattern& in_p, const std::vector<long>& frames_on_disk,
    const std::vector<sequence::FrameJob>& todo, double tau, bool quiet) {
  std::map<long, std::map<std::string, std::string>> out;
  if (plan.smoothed_params.empty() || !(tau > 0) || todo.empty()) return out;
  std::vector<long> todo_frames;
  for (const auto& j : todo) todo_frames.push_back(j.frame);
  const std::vector<long> frames = sequence::smoothing_neighbours(frames_on_disk, todo_frames, long(std::ceil(3 * tau)));
  if (frames.empty()) return out;  // no input to measure: the frames fail with their own message
  const std::size_t k = plan.smoothed_params.size();
  std::vector<std::vector<double>> series(k, std::vector<double>(frames.size(), NAN));
  std::mutex m;
  std::atomic<std::size_t> next{0};
  // A long shot's pre-pass takes a while before the first frame starts: it shows its count.
  StageProgress progress("cgtmo apply: statistics for temporal smoothing", quiet);
  const StageCallback report = progress.callback();
  std::size_t measured = 0;
  auto work = [&]() {
    for (std::size_t i; (i = next.fetch_add(1)) < frames.size();) {
      if (g_cancel.load()) return;
      std::vector<double> v;
      try {
        v = sequence::measure_frame(plan, in_p.format(frames[i]));
      } catch (const std::exception&) {
        // A frame that cannot be measured fails later with its own message; as a neighbour it is skipped.
      }
      std::lock_guard<std::mutex> lock(m);
      for (std::size_t p = 0; p < k && p < v.size(); ++p) series[p][i] = v[p];
      if (report) report(Stage{"frames measured", int(++measured), int(frames.size())});
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, thread_count()); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  // Frames missing between the inputs count as missing neighbours (the smoothing is sparse: a gap
  // of any length costs nothing).
  for (std::size_t p = 0; p < k; ++p) {
    const auto smooth = sequence::smooth_in_stops_at(frames, series[p], todo_frames, tau);
    for (std::size_t t = 0; t < todo.size(); ++t) {
      const double v = smooth[t];
      if (std::isfinite(v) && v > 0) {
        std::ostringstream s;
        s.precision(17);
        s << v;
        out[todo[t].frame][plan.smoothed_params[p]] = s.str();
      }
    }
  }
  if (!quiet)
    std::cerr << "cgtmo apply: statistics (" << [&] {
      std::string n;
      for (const auto& p : plan.smoothed_params) n += (n.empty() ? "" : ", ") + p;
      return n;
    }() << ") measured on " << frames.size() << " frames and smoothed over time (sigma " << tau << " frames; --temporal 0 turns it off)\n";
  return out;
}

}  // namespace

std::vector<std::string> files_read_by(const std::string& input, bool reads_companions, const std::string& probe,
                                       const std::string& sidecar) {
  if (!reads_companions) return {input};
  return {input, probe.empty() ? io::probe_path_for(input) : probe, sidecar.empty() ? io::sidecar_path_for(input) : sidecar};
}

// What --json prints for a sequence: the run's facts and one entry per frame (the single-file
// object's keys where they mean the same).
nlohmann::json sequence_json(const SequenceOptions& o, const sequence::BatchSummary& sum, int concurrent,
                             const std::string& why, bool interrupted, const sequence::FrameWarnings& warnings) {
  nlohmann::json warned = nlohmann::json::array();
  for (const auto& g : warnings.groups())
    warned.push_back({{"frames", sequence::format_frame_ranges(g.frames)}, {"message", g.message}});
  nlohmann::json frames = nlohmann::json::array();
  for (const auto& r : sum.outcomes) {
    nlohmann::json f = {{"frame", r.job.frame}, {"input", r.job.input}, {"output", r.job.output},
                        {"status", sequence::status_name(r.status)}};
    if (r.status == sequence::FrameStatus::Done) f["ms"] = r.ms;
    if (r.status == sequence::FrameStatus::Failed) f["error"] = r.error;
    frames.push_back(f);
  }
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [k, v] : o.provenance.params) params[k] = v;
  nlohmann::json j = {{"input", o.in_pattern},
                      {"output", o.out_pattern},
                      {"operator", o.provenance.op},
                      {"parameters", params},
                      {"exposure_ev", o.provenance.exposure_ev},
                      {"colorspace", o.provenance.colorspace},
                      {"temporal_sigma", o.provenance.temporal_sigma},
                      {"concurrent_frames", concurrent},
                      {"concurrency_limited_by", why},
                      {"seconds", sum.seconds},
                      {"done", sum.done},
                      {"skipped", sum.skipped},
                      {"failed", sum.failed},
                      {"not_started", sum.cancelled},
                      {"interrupted", interrupted},
                      {"warnings", warned},
                      {"frames", frames}};
  if (o.provenance.encode_display) {
    j["display"] = o.provenance.display;
    j["view"] = o.provenance.view;
  }
  return j;
}

int run_apply_sequence(const FrameProcessor& process, const sequence::StatisticsPlan& plan, const SequenceOptions& o) {
  const sequence::FramePattern in_p = sequence::FramePattern::parse(o.in_pattern);
  // --dry-run answers for frames not rendered yet ('missing'); --list-frames lists what a run would
  // do and refuses what it refuses (cgtmo-slurm's check before it queues anything).
  sequence::SequenceRequest request{o.in_pattern, o.out_pattern, o.frames, folder_names(in_p), o.reads_companions,
                                    o.dry_run};
  const sequence::SequencePlan planned = sequence::plan_sequence(request);
  for (const auto& w : planned.warnings) std::cerr << "cgtmo apply: warning: " << w << "\n";
  const std::vector<sequence::FrameJob>& jobs = planned.jobs;
  // Checked before any work: the output folder, and that no frame overwrites a file of any frame
  // (by canonical path and by inode: symlinks, hard links and `./` spellings are seen through).
  for (const auto& j : jobs) io::check_output_path(j.output, j.input);
  std::vector<std::string> outputs;
  for (const auto& j : jobs) outputs.push_back(j.output);
  io::check_outputs_are_not_inputs(outputs, planned.inputs);

  if (o.list_frames) {
    for (const auto& j : jobs) std::cout << j.frame << "\n";
    return 0;
  }
  // What each frame's output must record to count as done (sequence/provenance.h).
  std::vector<sequence::FrameCheck> checks;
  for (const auto& j : jobs) {
    sequence::FrameCheck c = sequence::check_frame(j, sequence::make_provenance(o.provenance, files_read_by(j.input, o.reads_companions)));
    if (o.force && c.state != sequence::FrameState::Missing) c = {sequence::FrameState::Todo, c.state == sequence::FrameState::Todo ? "" : "--force"};
    checks.push_back(std::move(c));
  }
  if (o.dry_run) {
    // "todo" for a stale output too (with why): scripts read the first word (done = "skip").
    // One line per frame: the paths and the reason (values decoded from the output's record) are
    // printed escaped, so no name or record can start a line of its own or command the terminal.
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      const auto& c = checks[i];
      std::cout << (c.state == sequence::FrameState::Stale ? "todo" : sequence::state_name(c.state)) << " " << jobs[i].frame
                << " " << printable(jobs[i].input) << " " << printable(jobs[i].output);
      if (!c.reason.empty())
        std::cout << " (" << (c.state == sequence::FrameState::Stale ? "made otherwise: " : "") << printable(c.reason) << ")";
      std::cout << "\n";
    }
    return 0;
  }

  const io::RemovedLeftovers stale = io::remove_stale_temps({outputs.begin(), outputs.end()});
  if (stale.total() && !o.quiet) std::cerr << "cgtmo apply: " << stale.describe("temporary file") << "\n";

  // Frames in flight: as many as threads allow and the memory budget holds. One frame holds its
  // beauty as float32 plus the decoder's and encoder's buffers: about 3x the float image.
  const int threads = thread_count();
  const double budget = o.max_memory_mb > 0 ? o.max_memory_mb : default_memory_mb();
  const Allocation& allotted = process_allocation();
  const std::string budget_text =
      o.max_memory_mb > 0 ? "--max-memory " + mb_text(budget)
                          : mb_text(budget) + ", half of " + the(allotted.memory_source);
  int concurrent = threads;
  // Why `concurrent` frames run at once, for the summary when that is fewer than the frames.
  std::string why = o.threads > 0 ? "--threads " + std::to_string(threads)
                                  : std::to_string(threads) + (threads == 1 ? " CPU" : " CPUs") + " from " +
                                        the(allotted.cpus_source);
  for (const auto& j : jobs) {
    std::error_code ec;
    if (!fs::exists(j.input, ec)) continue;
    try {
      const io::FileChannels fc = io::read_header(j.input);
      const double frame_mb = double(fc.width) * fc.height * 4 * sizeof(float) * 3 / (1024.0 * 1024.0);
      const double fit = budget / std::max(frame_mb, 1e-3);
      concurrent = std::max(1, int(std::min<double>(threads, fit)));
      if (fit < threads)
        why = "memory for " + std::to_string(concurrent) + ", ~" + mb_text(frame_mb) + " a frame in " + budget_text;
      if (budget < frame_mb && !o.quiet)
        std::cerr << "cgtmo apply: warning: the memory budget (" << budget_text << ") is below one frame's ~"
                  << mb_text(frame_mb) << "; running one frame at a time\n";
    } catch (const DataError&) {
    }
    break;
  }

  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  struct sigaction old_int {}, old_term {}, old_hup {};
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  sigaction(SIGHUP, &sa, &old_hup);

  const bool tty = ::isatty(2);
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t processed = 0;
  // Progress: on a terminal one bar on stderr, with the stage of the frame that last moved (a
  // long frame shows where it is); elsewhere a line per frame and per stage on stdout.
  std::mutex print;
  std::string bar, stage_note;
  auto draw = [&] {
    std::cerr << "\r\033[K" << bar << (stage_note.empty() ? "" : "  | ") << stage_note << std::flush;
  };
  sequence::BatchOptions bo;
  bo.fail_fast = o.fail_fast;
  bo.concurrent_frames = concurrent;
  std::vector<char> up_to_date(jobs.size(), 0);
  std::map<long, std::size_t> index_of;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    up_to_date[i] = checks[i].state == sequence::FrameState::UpToDate;
    index_of[jobs[i].frame] = i;
  }
  bo.up_to_date = [&](const sequence::FrameJob& j) { return up_to_date[index_of.at(j.frame)] != 0; };
  bo.on_frame = [&](const sequence::FrameOutcome& r, std::size_t finished, std::size_t total) {
    std::lock_guard<std::mutex> lock(print);
    if (r.status == sequence::FrameStatus::Done || r.status == sequence::FrameStatus::Failed) ++processed;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double fps = processed / std::max(elapsed, 1e-6);
    const double left = processed ? double(total - finished) / fps : NAN;
    if (r.status == sequence::FrameStatus::Failed)
      std::cerr << (tty ? "\r\033[K" : "") << "cgtmo apply: frame " << r.job.frame << " failed: " << r.error << "\n";
    if (o.quiet) return;
    if (tty) {
      const int width = 30, filled = int(width * finished / std::max<std::size_t>(total, 1));
      std::ostringstream b;
      b << "[" << std::string(filled, '#') << std::string(width - filled, '-') << "] " << finished << "/" << total
        << " frames  " << std::fixed << std::setprecision(2) << fps << " fps  " << human_time(left) << " left";
      bar = b.str();
      stage_note.clear();
      draw();
    } else {
      std::cout << "[" << finished << "/" << total << "] frame " << r.job.frame << " " << sequence::status_name(r.status);
      if (r.status == sequence::FrameStatus::Done) std::cout << " " << int(r.ms + 0.5) << " ms -> " << r.job.output;
      std::cout << "\n" << std::flush;
    }
  };
  auto on_stage = [&](long frame, const Stage& st) {
    if (o.quiet || g_cancel.load()) return;
    std::lock_guard<std::mutex> lock(print);
    if (tty) {
      stage_note = "frame " + std::to_string(frame) + ": " + st.name + " (" + std::to_string(st.index) + "/" + std::to_string(st.count) + ")";
      if (bar.empty()) bar = "[" + std::string(30, '-') + "] 0/" + std::to_string(jobs.size()) + " frames";
      draw();
    } else {
      std::cout << "frame " << frame << ": " << st.name << " (" << st.index << "/" << st.count << ")\n" << std::flush;
    }
  };
  std::vector<sequence::FrameJob> todo;
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (!up_to_date[i]) todo.push_back(jobs[i]);
  const auto overrides = smoothed_statistics(plan, in_p, planned.frames_on_disk, todo, o.temporal, o.quiet);
  sequence::FrameWarnings warnings(in_p);
  const std::map<std::string, std::string> none;
  const auto sum = sequence::run_batch(
      jobs,
      [&](const sequence::FrameJob& j) {
        const auto it = overrides.find(j.frame);
        pipeline::FileHooks hooks;
        // Taken when the frame starts: its inputs as they are read now.
        hooks.description = sequence::make_provenance(o.provenance, files_read_by(j.input, o.reads_companions)).text();
        hooks.on_stage = [&on_stage, frame = j.frame](const Stage& st) { on_stage(frame, st); };
        hooks.warn = [&warnings, frame = j.frame](const std::string& msg) { warnings.add(frame, msg); };
        process(j, it == overrides.end() ? none : it->second, hooks);
      },
      bo, &g_cancel);
  if (tty && !o.quiet) std::cerr << "\n";
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  sigaction(SIGHUP, &old_hup, nullptr);

  // Warnings are printed whatever -q says, as for one file.
  for (const auto& line : warnings.lines()) std::cerr << "cgtmo apply: warning: " << printable(line) << "\n";
  std::ostringstream s;
  s << "cgtmo apply: " << jobs.size() << " frames in " << std::fixed << std::setprecision(1) << sum.seconds << " s ("
    << concurrent << " at a time" << (std::size_t(concurrent) < jobs.size() ? ": " + why : "") << "): " << sum.done << " done, " << sum.skipped << " skipped, " << sum.failed << " failed";
  if (sum.cancelled) s << ", " << sum.cancelled << " not started (" << (g_cancel.load() ? "interrupted" : "--fail-fast") << ")";
  if (!o.quiet || sum.failed || sum.cancelled) std::cerr << s.str() << "\n";
  if (sum.failed) {
    std::vector<long> failed;
    for (const auto& r : sum.outcomes)
      if (r.status == sequence::FrameStatus::Failed) failed.push_back(r.job.frame);
    std::cerr << "failed frames: " << sequence::format_frame_ranges(failed) << "\n";
  }
  const int rc = g_cancel.load() ? 130 : sum.failed ? 1 : 0;
  if (o.json) std::cout << json_text(sequence_json(o, sum, concurrent, why, g_cancel.load(), warnings)) << "\n" << std::flush;
  return rc;
}

}  // namespace cgtmo::cli
