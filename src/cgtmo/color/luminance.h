#pragma once
// Luminance of linear Rec.709 RGB (Rec.709 weights on linear Rec.709 input, cgtmo's working space).

namespace cgtmo::color {

inline constexpr float kLumR = 0.2126f;
inline constexpr float kLumG = 0.7152f;
inline constexpr float kLumB = 0.0722f;

template <class T>
inline T luminance(T r, T g, T b) {
  return T(kLumR) * r + T(kLumG) * g + T(kLumB) * b;
}

}  // namespace cgtmo::color
