#pragma once
// Runs one registry operator over an interleaved RGB(A) buffer: exposure, image statistics (only
// when a parameter defaults from them), then the operator, in parallel over rows.
#include <map>
#include <memory>
#include <string>

#include "cgtmo/operators/operator.h"

namespace cgtmo::operators {

struct ToneMapRequest {
  std::string op;
  std::map<std::string, std::string> params;  // user-given key=value
  double exposure_ev = 0.0;                   // applied before the operator, for every operator
};

struct ToneMapResult {
  const OperatorDef* op = nullptr;
  ParamValues params;          // as resolved (defaults and image statistics filled in)
  bool used_image_stats = false;
  ImageStats stats;            // valid when used_image_stats
  Kind kind = Kind::PerChannel;
};

// Statistics of the beauty, accumulated in double.
ImageStats compute_image_stats(const float* px, std::size_t count, int channels);

// Validates the request, builds the evaluator (throws UsageError / DataError) and applies it.
ToneMapResult tonemap(float* px, std::size_t count, int channels, const ToneMapRequest& request);

// Builds the evaluator only (for the baker and tests): stats may be null when none is needed.
std::unique_ptr<Evaluator> make_evaluator(const OperatorDef& op, const std::map<std::string, std::string>& given,
                                          const ImageStats* stats, ParamValues* resolved = nullptr);

}  // namespace cgtmo::operators
