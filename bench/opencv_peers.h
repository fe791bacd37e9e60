#pragma once
// The OpenCV ximgproc peers of the speed-against-error benchmark (docs/platform.md): dtFilter with a
// 4-channel guide, the adaptive-manifold filter with the 9-channel G-buffer guide, and
// jointBilateralFilter with a 3-channel guide. Benchmark-only: built into `cgtmo` when
// libopencv-contrib-dev is present (CGTMO_HAVE_OPENCV_PEERS), never into the library.
#include <functional>
#include <string>
#include <vector>

#include "cgtmo/filters/guide.h"

namespace cgtmo::bench {

struct PeerMethod {
  std::string method, setting;
  // Filters in.log_lum into out (width*height); may throw std::exception.
  std::function<void(const filters::GuidedInput& in, float* out)> run;
  int max_runs = 0;  // > 0: time at most this many runs (the slow ones)
};

// The peers with the guide built from `in` once (channels scaled by the filter's sigmas, so that
// one sigma is one unit in every guide dimension). `median_sigma_pos`: the world-space sigma_pos
// used for the whole frame (OpenCV's filters take one range sigma).
std::vector<PeerMethod> opencv_peers(const filters::GuidedInput& in, const filters::FilterParams& p,
                                     float median_sigma_pos);

// Makes OpenCV's own pool use n threads (its filters do not use cgtmo's pool).
void opencv_set_threads(int n);
std::string opencv_version();

}  // namespace cgtmo::bench
