#include "cgtmo/color/matrix.h"

namespace cgtmo::color {

Mat3 Mat3::inverse() const {
  const auto& a = m;
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  const double s = 1.0 / det;
  Mat3 r;
  r.m = {{{c00 * s, (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s, (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s},
          {c01 * s, (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s, (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s},
          {c02 * s, (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s, (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s}}};
  return r;
}

Mat3 rec709_to_ap1() {
  // Values as published with the ACES/OCIO reference configs (sRGB primaries to AP1, Bradford CAT).
  Mat3 r;
  r.m = {{{0.6130973609, 0.3395229134, 0.0473793000},
          {0.0701942928, 0.9163556009, 0.0134526528},
          {0.0206155850, 0.1095697729, 0.8698151808}}};
  return r;
}

Mat3 ap1_to_rec709() { return rec709_to_ap1().inverse(); }

}  // namespace cgtmo::color
