#pragma once
// The LUT error audit: what OpenColorIO produces through a baked transform, display-encoded for
// the sRGB display, against the analytic operator (the registry's evaluator, clamped) encoded with
// the IEC 61966-2-1 formula in double. Errors are in 10-bit code values (1 = 1/1023).
#include <OpenColorIO/OpenColorIO.h>

#include <vector>

#include "cgtmo/operators/operator.h"

namespace cgtmo::bake {

namespace OCIO = OCIO_NAMESPACE;

// The input domain, as RGB triples: every non-negative finite half-float value (0 .. 65504) as a
// grey and on each primary alone (so every gap between LUT nodes is visited at half resolution),
// log-uniform random colours over 2^-24 .. 65504 with some channels zero, and saturated hue
// sweeps over 32 stops. Deterministic.
const std::vector<float>& audit_samples();

struct AuditResult {
  double max_cv = 0;    // maximum over samples of the largest channel error
  double p999_cv = 0;   // 99.9th percentile of that
  float worst[3] = {0, 0, 0};  // the input where the maximum occurs
};

// `encoded` maps scene-linear to sRGB-encoded display values (the view as an application sees it).
AuditResult audit(const OCIO::ConstCPUProcessorRcPtr& encoded, const operators::Evaluator& reference,
                  const std::vector<float>& samples = audit_samples());

// OCIO CPU throughput of `proc` on one thread, Mpixel/s: median of 5 runs over 1920x1080 RGB.
double ocio_throughput_mpix(const OCIO::ConstCPUProcessorRcPtr& proc);

// IEC 61966-2-1 sRGB encoding of display-linear values (the audit's reference encoding).
double srgb_encode(double linear);

}  // namespace cgtmo::bake
