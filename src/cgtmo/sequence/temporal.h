#pragma once
// Statistics held steady over a shot: per-frame adaptation values (Lw_max, Lw_a, white points)
// smoothed over time so that a tone-mapped sequence does not flicker when noise, fireflies or a
// passing highlight move a frame's statistics.
//
// The smoothing is a Gaussian over frames in log2 (stops), centred (no lag: a whole shot is known
// before it is tone-mapped), with standard deviation `tau` frames; near the ends of the shot the
// weights are renormalised over the frames that exist. tau = 0 returns the values unchanged.
#include <vector>

namespace cgtmo::sequence {

// `values` in frame order (positive; non-positive or non-finite entries are ignored as
// neighbours and replaced by the smoothed value of the others).
std::vector<double> smooth_in_stops(const std::vector<double>& values, double tau);

// The same smoothing over a sparse shot: `values[i]` belongs to frame `frames[i]` (ascending);
// frames not listed are missing neighbours. Returns the smoothed value at each frame of `at`
// (NaN where no usable frame lies within 3 tau; with tau = 0, the frame's own value or NaN).
// Work grows with the frames listed and within 3 tau, not with the span of the frame numbers.
std::vector<double> smooth_in_stops_at(const std::vector<long>& frames, const std::vector<double>& values,
                                       const std::vector<long>& at, double tau);

// Mean absolute frame-to-frame change, in stops, of a positive series (the flicker measure of
// docs/sequences.md when given mean display luminances).
double mean_abs_step_stops(const std::vector<double>& values);

}  // namespace cgtmo::sequence
