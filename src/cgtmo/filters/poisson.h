#pragma once
// The sampling pattern of the paper's fast evaluation (its reference [22], Banterle et al. 2012):
// S integer offsets inside the window, drawn with the density of the spatial Gaussian and kept
// Poisson-disk apart. The centre (0, 0) is always the first offset.
#include <vector>

namespace cgtmo::filters {

struct Offset {
  int dx = 0, dy = 0;
};

// Deterministic for a given (samples, sigma, radius, seed). The minimum distance follows the
// density (points are denser near the centre) and shrinks until S points fit.
std::vector<Offset> poisson_disk_offsets(int samples, float sigma_px, int radius, unsigned seed);

}  // namespace cgtmo::filters
