#pragma once
// Farbman, Fattal, Lischinski, Szeliski, "Edge-preserving decompositions for multi-scale tone and
// detail manipulation", SIGGRAPH 2008: the weighted-least-squares (WLS) smoothing that the CG-TMO
// paper uses as its WLS-TMO baseline. The base layer u minimises
//   sum_p (u_p - g_p)^2 + lambda * sum_{p~q} a_pq (u_p - u_q)^2,
//   a_pq = 1 / (|l_p - l_q|^alpha + epsilon),
// over 4-connected neighbours, with g the input (log10 luminance) and l the natural log of
// luminance (Farbman's guide: l = ln(10) g). This is one sparse symmetric positive-definite
// system (I + lambda L_a) u = g, solved with Eigen's conjugate gradient (Jacobi preconditioner).
//
// Same signature shape and background rule as the cross-bilateral evaluations (guide.h): only
// GuidedInput::log_lum and ::mask are read; background pixels (mask <= 0.5 or non-finite log_lum)
// are not unknowns, are not coupled to geometry, and get base = input (global operator there).
#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

struct WlsParams {
  double alpha = 1.2;       // gradient sensitivity (the CG-TMO paper: 1.2)
  double lambda = 0.125;    // smoothness (the CG-TMO paper: 0.125)
  double epsilon = 1e-4;    // keeps a_pq finite where the guide is flat (Farbman's code)
  double tolerance = 1e-6;  // conjugate gradient: relative residual
  int max_iterations = 5000;
};

struct WlsReport {
  int unknowns = 0;
  int iterations = 0;
  double residual = 0;  // relative, as Eigen reports it
};

void wls_filter(const GuidedInput& in, const WlsParams& p, float* out_base_log, WlsReport* report = nullptr);

}  // namespace cgtmo::filters
