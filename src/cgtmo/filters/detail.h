#pragma once
// Internal to filters/: what the evaluations of the cross-bilateral filter share.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "cgtmo/filters/guide.h"

namespace cgtmo::filters::detail {

// A pixel is a source and gets filtered when the mask says geometry and every channel the active
// groups read is finite (guide.h: anything else is background).
inline bool finite3(const Channel* c, std::size_t i) {
  return std::isfinite(c[0][i]) && std::isfinite(c[1][i]) && std::isfinite(c[2][i]);
}
inline bool pixel_valid(const GuidedInput& in, unsigned groups, std::size_t i) {
  if (in.mask && !(in.mask[i] > 0.5f)) return false;
  if (!std::isfinite(in.log_lum[i])) return false;
  if ((groups & kGuidePosition) && !finite3(in.position, i)) return false;
  if ((groups & kGuideNormal) && !finite3(in.normal, i)) return false;
  if ((groups & kGuideAlbedo) && !finite3(in.albedo, i)) return false;
  return true;
}

// 1 / (2 sigma_pos(x)^2) at pixel i; 0 (no position factor at this centre) when the position group
// is off or the footprint is not positive and finite.
inline double position_coefficient(const GuidedInput& in, const FilterParams& p, std::size_t i) {
  if (!(p.groups & kGuidePosition)) return 0.0;
  const double fp = in.footprint ? double(in.footprint[i]) : double(p.footprint);
  if (!(fp > 0.0) || !std::isfinite(fp)) return 0.0;
  const double s = fp * double(p.sigma_pos_footprints);
  return 1.0 / (2.0 * s * s);
}

// One float plane, left uninitialised on allocation: make_planar writes every element from the
// pool's threads (a std::vector would first zero it on one thread, and page it in there).
class Plane {
 public:
  void allocate(std::size_t n) { data_.reset(new float[n]), size_ = n; }
  bool empty() const { return size_ == 0; }
  float* data() { return data_.get(); }
  const float* data() const { return data_.get(); }
  float& operator[](std::size_t i) { return data_[i]; }
  float operator[](std::size_t i) const { return data_[i]; }

 private:
  std::unique_ptr<float[]> data_;
  std::size_t size_ = 0;
};

// The frame's channels, contiguous and sanitised: invalid pixels have valid = 0 and zeros
// elsewhere. The reference evaluations (exact, poisson, bilateral) work on this copy.
struct PlanarFrame {
  int width = 0, height = 0;
  Plane lum, valid, kpos;  // kpos: position_coefficient per pixel
  Plane guide[9];          // P xyz, N xyz, A xyz (only the active groups are filled)
};
PlanarFrame make_planar(const GuidedInput& in, const FilterParams& p, bool with_guide);

// One row of the frame, sanitised by pixel_valid's rule: valid (1 or 0), and where valid the log
// luminance, the active groups' guide channels and the position coefficient times kpos_scale
// (position_coefficient; log2 e for the kernels that weigh with exp2), zeros elsewhere. g[k] is
// written for the active groups only, kpos only with the position group. Each buffer holds the
// row's width. The one implementation behind make_planar and the fast evaluation's rows.
struct RowOut {
  float* g[9];
  float *valid, *lum, *kpos;
};
void sanitize_row(const GuidedInput& in, const FilterParams& p, unsigned groups, int y, const RowOut& r, float kpos_scale);

// log2(e): the SIMD evaluations weigh with exp2, so their coefficients are scaled by it.
constexpr double kLog2e = 1.4426950408889634;

// exp(x) for x <= 0 in double, branch-free so that loops over it vectorise; relative error below
// 1e-15 (degree-12 Taylor on |r| <= ln2/2); 0 below -700.
inline double exp_neg(double x) {
  x = x < -700.0 ? -700.0 : x;
  const double kLn2Hi = 0.6931471803691238, kLn2Lo = 1.9082149292705877e-10;
  const double shifter = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  double n = (x * kLog2e + shifter) - shifter;
  const double r = (x - n * kLn2Hi) - n * kLn2Lo;
  double s = 1.0 / 479001600.0;  // 1/12!
  const double inv_fact[12] = {1.0 / 39916800.0, 1.0 / 3628800.0, 1.0 / 362880.0, 1.0 / 40320.0, 1.0 / 5040.0,
                               1.0 / 720.0,      1.0 / 120.0,     1.0 / 24.0,     1.0 / 6.0,    0.5,
                               1.0,              1.0};
  for (int k = 0; k < 12; ++k) s = s * r + inv_fact[k];
  const int64_t bits = (int64_t(n) + 1023) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return s * scale;
}

// Rows [0, height) in parallel; f(y) for each row.
template <class F>
void for_each_row(int height, F&& f);

}  // namespace cgtmo::filters::detail

#include "cgtmo/util/parallel.h"

namespace cgtmo::filters::detail {
template <class F>
void for_each_row(int height, F&& f) {
  parallel_rows(height, [&](int64_t b, int64_t e) {
    for (int64_t y = b; y < e; ++y) f(int(y));
  });
}
}  // namespace cgtmo::filters::detail
