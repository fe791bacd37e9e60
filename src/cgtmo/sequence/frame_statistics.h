#pragma once
// The per-frame statistics that temporal smoothing holds steady, measured without tone-mapping:
// for global operators the image statistics their parameters default from (white, lw_max, lw_a),
// for the scene operators (cgtmo, wls) Lw_max from the lights and Lw_a from the probe.
#include <map>
#include <string>
#include <vector>

#include "cgtmo/io/read_options.h"

namespace cgtmo::sequence {

struct StatisticsPlan {
  std::string op;
  std::map<std::string, std::string> params;  // user-given; statistics they fix are not measured
  double exposure_ev = 0.0;
  std::string layer;
  // The input colour space and the OCIO config naming it (pipeline::ApplyOptions): statistics are
  // measured on the input converted to linear Rec.709, as the frames are tone-mapped.
  std::string colorspace, colorconfig;
  io::ReadOptions read;  // window and EXR view, as the frames are read
  // The parameters to hold steady (image- or scene-derived and not given by the user).
  std::vector<std::string> smoothed_params;
};

// Which parameters of `op` come from frame statistics. Empty: nothing to smooth.
StatisticsPlan plan_statistics(const std::string& op, const std::map<std::string, std::string>& params,
                               double exposure_ev, const std::string& layer);

// Measures one frame: one value per plan.smoothed_params, in that order. Throws DataError.
std::vector<double> measure_frame(const StatisticsPlan& plan, const std::string& input);

}  // namespace cgtmo::sequence
