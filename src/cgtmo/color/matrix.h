#pragma once
// Row-major 3x3 colour matrices. out[i] = sum_j m[i][j] * in[j]: every row reads v[0], v[1], v[2]
// (a widely copied helper reads v[1] in place of v[0] on rows two and three; docs/platform.md).
#include <array>

namespace cgtmo::color {

struct Mat3 {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

  static Mat3 identity() { return Mat3{}; }

  template <class T>
  void apply(T& r, T& g, T& b) const {
    const T x = T(m[0][0]) * r + T(m[0][1]) * g + T(m[0][2]) * b;
    const T y = T(m[1][0]) * r + T(m[1][1]) * g + T(m[1][2]) * b;
    const T z = T(m[2][0]) * r + T(m[2][1]) * g + T(m[2][2]) * b;
    r = x;
    g = y;
    b = z;
  }

  Mat3 operator*(const Mat3& o) const {
    Mat3 p;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) p.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return p;
  }

  Mat3 inverse() const;
};

// Linear Rec.709 <-> ACES AP1 (ACEScg), D65 <-> D60 via Bradford; used by operators that grade in AP1.
Mat3 rec709_to_ap1();
Mat3 ap1_to_rec709();

}  // namespace cgtmo::color
