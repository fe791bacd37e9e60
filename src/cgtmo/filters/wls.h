#pragma once
// Farbman, Fattal, Lischinski, Szeliski, "Edge-preserving decompositions for multi-scale tone and
// detail manipulation", SIGGRAPH 2008: the weighted-least-squares (WLS) smoothing that the CG-TMO
// paper uses as its WLS-TMO baseline. The base layer u minimises
//   sum_p (u_p - g_p)^2 + lambda * sum_{p~q} a_pq (u_p - u_q)^2,
//   a_pq = 1 / (|l_p - l_q|^alpha + epsilon),
// over 4-connected neighbours, with g the input (log10 luminance here) and l the natural log of
// luminance (Farbman's choice of guide). This is one sparse symmetric positive-definite system
// (I + lambda L_a) u = g, solved with Eigen's preconditioned conjugate gradient.
#include <vector>

namespace cgtmo::filters {

struct WlsParams {
  double alpha = 1.2;      // gradient sensitivity (paper: 1.2)
  double lambda = 0.125;   // smoothness (paper: 0.125)
  double epsilon = 1e-4;   // keeps a_pq finite where the guide is flat (as Farbman's code)
  double tolerance = 1e-6; // conjugate gradient relative residual
  int max_iterations = 2000;
};

struct WlsReport {
  int iterations = 0;
  double residual = 0;  // relative, as Eigen reports it
};

// log10_luminance: width*height values, row-major. Returns the smoothed base layer in the same
// units. Non-finite inputs are a caller error (the pipeline floors and sanitises first).
// `mask` (optional, width*height bytes, 1 = foreground): pixels whose mask differs are not
// coupled, so background and geometry do not smooth into each other.
std::vector<float> wls_filter(const float* log10_luminance, int width, int height, const WlsParams& params = {},
                              const unsigned char* mask = nullptr, WlsReport* report = nullptr);

}  // namespace cgtmo::filters
