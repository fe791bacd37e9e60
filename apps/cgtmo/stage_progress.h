#pragma once
// Stage progress of one file (cgtmo apply without a frame token): on a terminal one live line on
// stderr, cleared before the result is printed; elsewhere (logs, farm jobs) one line per stage on
// stdout, so a long frame is never silent.
#include <chrono>
#include <iostream>
#include <string>

#include "cgtmo/util/progress.h"

namespace cgtmo::cli {

class StageProgress {
 public:
  // `log`: where the line per stage goes off a terminal (stdout; a command whose stdout is its
  // result passes std::cerr).
  StageProgress(std::string prefix, bool quiet, std::ostream& log = std::cout);
  ~StageProgress();  // clears the live line (an error message then starts on a clean line)
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  StageCallback callback();
  void finish();  // clears the live line

 private:
  void report(const Stage& stage);
  std::string prefix_;
  std::ostream& log_;
  bool quiet_, tty_, drawn_ = false;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace cgtmo::cli
