#pragma once
// `cgtmo apply --json`: what one file's run did, as one JSON object on stdout (docs/outputs.md).
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cgtmo/local/apply_scene.h"
#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/util/progress.h"
#include "cgtmo/util/text.h"

namespace cgtmo::cli {

// Records when each stage starts; durations() gives each stage's milliseconds and the total.
class StageTimer {
 public:
  StageTimer();
  void mark(const Stage& s);
  nlohmann::json durations() const;  // {"read": ms, ..., "total": ms}

 private:
  std::chrono::steady_clock::time_point t0_;
  std::vector<std::pair<std::string, std::chrono::steady_clock::time_point>> marks_;
};

struct JsonRequest {
  std::string input, output, op;
  double exposure = 0;
  io::OutputFormat format;
};

// The facts both pipelines share: input, output, size, operator, exposure, colour, format.
nlohmann::json apply_json(const JsonRequest& r, const pipeline::ApplyReport& rep);
// The scene operators': the same, with the resolved parameters, scene statistics (Lw_max, Lw_a and
// their sources) and the guide's decisions, as --explain prints them.
nlohmann::json apply_json(const JsonRequest& r, const local::SceneApplyReport& rep);

}  // namespace cgtmo::cli
