#include "cgtmo/sequence/batch.h"

#include <chrono>
#include <mutex>
#include <thread>

namespace cgtmo::sequence {

const char* status_name(FrameStatus s) {
  switch (s) {
    case FrameStatus::Done: return "done";
    case FrameStatus::Skipped: return "skipped";
    case FrameStatus::Failed: return "failed";
    case FrameStatus::Cancelled: return "cancelled";
  }
  return "?";
}

BatchSummary run_batch(const std::vector<FrameJob>& jobs, const std::function<void(const FrameJob&)>& process,
                       const BatchOptions& opt, const std::atomic<bool>* cancel) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  BatchSummary sum;
  sum.outcomes.resize(jobs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex report;
  std::size_t finished = 0;

  auto worker = [&]() {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= jobs.size()) return;
      FrameOutcome o;
      o.job = jobs[i];
      const auto f0 = clock::now();
      if (stop.load() || (cancel && cancel->load())) {
        o.status = FrameStatus::Cancelled;
      } else if (opt.up_to_date && opt.up_to_date(o.job)) {
        o.status = FrameStatus::Skipped;
      } else {
        try {
          process(o.job);
          o.status = FrameStatus::Done;
        } catch (const std::exception& e) {
          o.status = FrameStatus::Failed;
          o.error = e.what();
          if (opt.fail_fast) stop.store(true);
        }
      }
      o.ms = std::chrono::duration<double, std::milli>(clock::now() - f0).count();
      std::lock_guard<std::mutex> lock(report);
      sum.outcomes[i] = o;
      if (o.status == FrameStatus::Cancelled) continue;
      ++finished;
      if (opt.on_frame) opt.on_frame(o, finished, jobs.size());
    }
  };
  const int n = std::max(1, std::min<int>(opt.concurrent_frames, int(jobs.size())));
  std::vector<std::thread> pool;
  for (int k = 1; k < n; ++k) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();

  for (const auto& o : sum.outcomes) {
    switch (o.status) {
      case FrameStatus::Done: ++sum.done; break;
      case FrameStatus::Skipped: ++sum.skipped; break;
      case FrameStatus::Failed: ++sum.failed; break;
      case FrameStatus::Cancelled: ++sum.cancelled; break;
    }
  }
  sum.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return sum;
}

}  // namespace cgtmo::sequence
