#pragma once
// The one non-finite / out-of-range policy (docs/numerics.md), applied to the beauty once, right
// after reading, and reported by the CLI:
//   NaN -> 0,  -Inf -> 0,  negative -> 0,  +Inf -> 65504,  finite values above 65504 -> 65504.
// 65504 is the half-float maximum: the top of every LUT domain, so the CLI and the LUTs agree.
// Alpha: NaN -> 0, then clamped to [0, 1].
#include <cstddef>
#include <string>

#include "cgtmo/scene/frame.h"

namespace cgtmo::scene {

inline constexpr float kMaxInputValue = 65504.0f;

struct SanitizeReport {
  std::size_t nan = 0, pos_inf = 0, neg_inf = 0, negative = 0, over_max = 0, alpha = 0;
  std::size_t total() const { return nan + pos_inf + neg_inf + negative + over_max + alpha; }
  std::string describe() const;  // "" when nothing was changed
};

SanitizeReport sanitize(Frame& f);
SanitizeReport sanitize(float* px, std::size_t count, int channels);

// The alpha rule for what is written (docs/exr-inputs.md, "Alpha"): an alpha above 0 at no pixel
// (0, negative or NaN everywhere) while some colour is above 0 is not coverage (a renderer that
// left it unset, OpenEXR's Carrots.exr), and as it stands it would make the whole output
// transparent. It is dropped: the frame becomes RGB. Returns the warning to print, or "" when
// the frame is left as it is.
std::string drop_alpha_without_coverage(Frame& f);

}  // namespace cgtmo::scene
