#pragma once
// Luminance of linear Rec.709 RGB (Rec.709 weights on linear Rec.709 input, cgtmo's working space).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace cgtmo::color {

inline constexpr float kLumR = 0.2126f;
inline constexpr float kLumG = 0.7152f;
inline constexpr float kLumB = 0.0722f;

template <class T>
inline T luminance(T r, T g, T b) {
  return T(kLumR) * r + T(kLumG) * g + T(kLumB) * b;
}

// The luminance of each pixel of an interleaved plane whose first three channels are RGB
// (`channels` 3 or more: alpha is skipped), as the statistics and the filters take it: negative
// and non-finite values count as 0.
inline std::vector<float> luminance_plane(const std::vector<float>& px, int channels) {
  const std::size_t n = px.size() / std::size_t(channels);
  std::vector<float> y(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = &px[i * std::size_t(channels)];
    const float v = luminance(p[0], p[1], p[2]);
    y[i] = std::isfinite(v) ? std::max(v, 0.f) : 0.f;
  }
  return y;
}

}  // namespace cgtmo::color
