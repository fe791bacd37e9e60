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
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/sequence/batch.h"
#include "cgtmo/sequence/frame_pattern.h"
#include "cgtmo/sequence/temporal.h"
#include "cgtmo/util/parallel.h"

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

// Frames whose input exists, found by listing the input's folder.
std::vector<long> frames_on_disk(const std::string& pattern_text) {
  const sequence::FramePattern p = sequence::FramePattern::parse(pattern_text);
  // Build a regex from the name with the frame replaced: prefix, digits, suffix.
  const std::string f0 = p.format(123456789);
  const auto at = f0.find("123456789");
  const std::string prefix = f0.substr(0, at), suffix = f0.substr(at + 9);
  fs::path dir = fs::path(prefix).parent_path();
  const std::string name_prefix = fs::path(prefix).filename().string();
  auto quote = [](const std::string& s) { return std::regex_replace(s, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"); };
  const std::regex re(quote(name_prefix) + "(-?[0-9]+)" + quote(suffix));
  std::set<long> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    std::smatch m;
    const std::string n = e.path().filename().string();
    if (std::regex_match(n, m, re) && m[1].length() >= p.width()) {
      const long f = std::stol(m[1]);
      if (p.format(f) == (dir.empty() ? n : (dir / n).string())) found.insert(f);
    }
  }
  return {found.begin(), found.end()};
}

std::string human_time(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char b[32];
  const long t = long(s + 0.5);
  std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  return b;
}

// The readers' budget: half of the RAM or of the cgroup limit (io/input_file.h).
double default_memory_mb() { return double(io::default_memory_budget()) / (1024.0 * 1024.0); }

// Smoothed statistics for the frames to do: measured on every input of the shot that lies within
// 3 sigma of one of them (so a chunk of a farm run sees the same neighbours as a whole run).
std::map<long, std::map<std::string, std::string>> smoothed_statistics(
    const sequence::StatisticsPlan& plan, const sequence::FramePattern& in_p, const std::vector<sequence::FrameJob>& todo,
    double tau, bool quiet) {
  std::map<long, std::map<std::string, std::string>> out;
  if (plan.smoothed_params.empty() || !(tau > 0) || todo.empty()) return out;
  const long radius = long(std::ceil(3 * tau));
  std::set<long> wanted;
  const std::vector<long> shot = frames_on_disk(in_p.text());
  const std::set<long> on_disk(shot.begin(), shot.end());
  for (const auto& j : todo)
    for (long f = j.frame - radius; f <= j.frame + radius; ++f)
      if (on_disk.count(f)) wanted.insert(f);
  std::vector<long> frames(wanted.begin(), wanted.end());
  const std::size_t k = plan.smoothed_params.size();
  std::vector<std::vector<double>> series(k, std::vector<double>(frames.size(), NAN));
  std::mutex m;
  std::atomic<std::size_t> next{0};
  auto work = [&]() {
    for (std::size_t i; (i = next.fetch_add(1)) < frames.size();) {
      if (g_cancel.load()) return;
      try {
        const auto v = sequence::measure_frame(plan, in_p.format(frames[i]));
        std::lock_guard<std::mutex> lock(m);
        for (std::size_t p = 0; p < k; ++p) series[p][i] = v[p];
      } catch (const std::exception&) {
        // A frame that cannot be measured fails later with its own message; as a neighbour it is skipped.
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, thread_count()); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  // Gaps between frames on disk count as missing neighbours: smooth over the frame axis.
  const long first = frames.front(), last = frames.back();
  for (std::size_t p = 0; p < k; ++p) {
    std::vector<double> dense(std::size_t(last - first + 1), NAN);
    for (std::size_t i = 0; i < frames.size(); ++i) dense[std::size_t(frames[i] - first)] = series[p][i];
    const auto smooth = sequence::smooth_in_stops(dense, tau);
    for (const auto& j : todo) {
      const double v = smooth[std::size_t(j.frame - first)];
      if (std::isfinite(v) && v > 0) {
        std::ostringstream s;
        s.precision(17);
        s << v;
        out[j.frame][plan.smoothed_params[p]] = s.str();
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

int run_apply_sequence(const FrameProcessor& process, const sequence::StatisticsPlan& plan, const SequenceOptions& o) {
  const sequence::FramePattern in_p = sequence::FramePattern::parse(o.in_pattern);
  if (!sequence::FramePattern::is_pattern(o.out_pattern))
    throw UsageError("output '" + o.out_pattern + "' needs a frame token (####, @@@@ or %04d) when the input is a sequence");
  const sequence::FramePattern out_p = sequence::FramePattern::parse(o.out_pattern);
  std::vector<long> frames = o.frames.empty() ? frames_on_disk(o.in_pattern) : sequence::parse_frame_range(o.frames);
  if (frames.empty()) throw DataError("no input frames match '" + o.in_pattern + "'");

  std::vector<sequence::FrameJob> jobs;
  std::set<std::string> outputs;
  for (long f : frames) {
    sequence::FrameJob j{f, in_p.format(f), out_p.format(f)};
    if (!outputs.insert(j.output).second) throw UsageError("two frames write the same output '" + j.output + "'");
    jobs.push_back(std::move(j));
  }
  // Checked before any work: the output folder, and that no frame would overwrite an input.
  for (const auto& j : jobs) io::check_output_path(j.output, j.input);

  if (o.list_frames) {
    for (long f : frames) std::cout << f << "\n";
    return 0;
  }
  if (o.dry_run) {
    for (const auto& j : jobs)
      std::cout << (!o.force && sequence::output_up_to_date(j.input, j.output) ? "skip " : "todo ") << j.frame << " "
                << j.input << " " << j.output << "\n";
    return 0;
  }

  int stale = 0;
  for (const auto& j : jobs) stale += io::remove_stale_temps(j.output);
  if (stale && !o.quiet) std::cerr << "cgtmo apply: removed " << stale << " temporary file(s) left by an interrupted run\n";

  // Frames in flight: as many as threads allow and the memory budget holds. One frame holds its
  // beauty as float32 plus the decoder's and encoder's buffers: about 3x the float image.
  const int threads = thread_count();
  const double budget = o.max_memory_mb > 0 ? o.max_memory_mb : default_memory_mb();
  int concurrent = threads;
  for (const auto& j : jobs) {
    std::error_code ec;
    if (!fs::exists(j.input, ec)) continue;
    try {
      const io::FileChannels fc = io::read_header(j.input);
      const double frame_mb = double(fc.width) * fc.height * 4 * sizeof(float) * 3 / (1024.0 * 1024.0);
      concurrent = std::max(1, std::min(threads, int(budget / std::max(frame_mb, 1e-3))));
      if (budget < frame_mb && !o.quiet)
        std::cerr << "cgtmo apply: warning: --max-memory " << budget << " MB is below one frame's ~" << int(frame_mb)
                  << " MB; running one frame at a time\n";
    } catch (const DataError&) {
    }
    break;
  }

  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  struct sigaction old_int {}, old_term {};
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);

  const bool tty = ::isatty(2);
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t processed = 0;
  sequence::BatchOptions bo;
  bo.force = o.force;
  bo.fail_fast = o.fail_fast;
  bo.concurrent_frames = concurrent;
  bo.on_frame = [&](const sequence::FrameOutcome& r, std::size_t finished, std::size_t total) {
    if (r.status == sequence::FrameStatus::Done || r.status == sequence::FrameStatus::Failed) ++processed;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double fps = processed / std::max(elapsed, 1e-6);
    const double left = processed ? double(total - finished) / fps : NAN;
    if (r.status == sequence::FrameStatus::Failed)
      std::cerr << (tty ? "\r\033[K" : "") << "cgtmo apply: frame " << r.job.frame << " failed: " << r.error << "\n";
    if (o.quiet) return;
    if (tty) {
      const int width = 30, filled = int(width * finished / std::max<std::size_t>(total, 1));
      std::cerr << "\r\033[K[" << std::string(filled, '#') << std::string(width - filled, '-') << "] " << finished << "/" << total
                << " frames  " << std::fixed << std::setprecision(2) << fps << " fps  " << human_time(left) << " left"
                << std::defaultfloat << std::flush;
    } else {
      std::cout << "[" << finished << "/" << total << "] frame " << r.job.frame << " " << sequence::status_name(r.status);
      if (r.status == sequence::FrameStatus::Done) std::cout << " " << int(r.ms + 0.5) << " ms -> " << r.job.output;
      std::cout << "\n" << std::flush;
    }
  };
  std::vector<sequence::FrameJob> todo;
  for (const auto& j : jobs)
    if (o.force || !sequence::output_up_to_date(j.input, j.output)) todo.push_back(j);
  const auto overrides = smoothed_statistics(plan, in_p, todo, o.temporal, o.quiet);
  const std::map<std::string, std::string> none;
  const auto sum = sequence::run_batch(
      jobs,
      [&](const sequence::FrameJob& j) {
        const auto it = overrides.find(j.frame);
        process(j, it == overrides.end() ? none : it->second);
      },
      bo, &g_cancel);
  if (tty && !o.quiet) std::cerr << "\n";
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);

  std::ostringstream s;
  s << "cgtmo apply: " << jobs.size() << " frames in " << std::fixed << std::setprecision(1) << sum.seconds << " s ("
    << concurrent << " at a time): " << sum.done << " done, " << sum.skipped << " skipped, " << sum.failed << " failed";
  if (sum.cancelled) s << ", " << sum.cancelled << " not started (" << (g_cancel.load() ? "interrupted" : "--fail-fast") << ")";
  if (!o.quiet || sum.failed || sum.cancelled) std::cerr << s.str() << "\n";
  if (sum.failed) {
    std::cerr << "failed frames:";
    for (const auto& r : sum.outcomes)
      if (r.status == sequence::FrameStatus::Failed) std::cerr << " " << r.job.frame;
    std::cerr << "\n";
  }
  if (g_cancel.load()) return 130;
  return sum.failed ? 1 : 0;
}

}  // namespace cgtmo::cli
