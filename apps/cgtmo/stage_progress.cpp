#include "stage_progress.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace cgtmo::cli {

StageProgress::StageProgress(std::string prefix, bool quiet, std::ostream& log)
    : prefix_(std::move(prefix)), log_(log), quiet_(quiet), tty_(::isatty(2) != 0), t0_(std::chrono::steady_clock::now()) {}

StageProgress::~StageProgress() { finish(); }

StageCallback StageProgress::callback() {
  if (quiet_) return {};
  return [this](const Stage& s) { report(s); };
}

void StageProgress::report(const Stage& s) {
  const double at = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  char when[32];
  std::snprintf(when, sizeof when, "%.1f s", at);
  if (!tty_) {
    log_ << prefix_ << ": " << s.name << " (" << s.index << "/" << s.count << ") at " << when << "\n" << std::flush;
    return;
  }
  // The last stage (the write) is short: the line goes, so the result prints on a clean line.
  if (s.index >= s.count) {
    finish();
    return;
  }
  std::cerr << "\r\033[K" << prefix_ << ": " << s.name << " (" << s.index << "/" << s.count << ")  " << when << std::flush;
  drawn_ = true;
}

void StageProgress::finish() {
  if (drawn_) std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

}  // namespace cgtmo::cli
