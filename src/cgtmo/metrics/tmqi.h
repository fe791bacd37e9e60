#pragma once
// TMQI, the Tone-Mapped image Quality Index (Yeganeh and Wang, IEEE TIP 22(2), 2013), following
// the authors' published v1.0 code where the paper leaves a detail open (docs/cgtmo.md):
//   - luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the HDR (linear) and of the LDR as stored
//     (display-encoded values on a 0-255 scale, not linearised);
//   - HDR luminance stretched to [0, round((2^32-1)/(max-min)) * (max-min)];
//   - local structural fidelity with an 11x11 Gaussian window (sigma 1.5) and 'valid' filtering
//     (no border padding), C1 = 0.01, C2 = 10, Mannos CSF at 16, 8, 4, 2, 1 cycles/degree;
//     between scales a 2x2 mean with symmetric borders, keeping every other pixel;
//   - S = prod_l max(s_l, 0)^w_l with w = (0.0448, 0.2856, 0.3001, 0.2363, 0.1333) (v1.0 has no
//     max: a negative s_l makes its S complex);
//   - statistical naturalness from the mean (Gaussian, 115.94 / 27.99) and the mean standard
//     deviation of 11x11 blocks of the zero-padded image (Beta(4.4, 10.1) of std / 64.29);
//   - Q = a S^alpha + (1 - a) N^beta, a = 0.8012, alpha = 0.3046, beta = 0.7088.
#include <array>
#include <vector>

namespace cgtmo::metrics {

inline constexpr int kTmqiScales = 5;
inline constexpr int kTmqiWindow = 11;
// The fifth scale is ceil(n / 16) pixels wide and must still hold one 11x11 window.
inline constexpr int kTmqiMinSize = 16 * (kTmqiWindow - 1) + 1;  // 161

struct TmqiResult {
  double q = 0, s = 0, n = 0;
  std::array<double, kTmqiScales> s_local{};  // mean local fidelity per scale, finest first
};

// A single-channel image in double, row-major.
struct Plane {
  int width = 0, height = 0;
  std::vector<double> v;
  double& at(int x, int y) { return v[std::size_t(y) * width + x]; }
  double at(int x, int y) const { return v[std::size_t(y) * width + x]; }
};

// The parts, exposed so that each can be checked on its own.
// hdr: luminance already stretched as above; ldr: luminance on 0-255.
double tmqi_local_fidelity(const Plane& hdr, const Plane& ldr, double cycles_per_degree);
std::array<double, kTmqiScales> tmqi_fidelity_scales(Plane hdr, Plane ldr);
double tmqi_structural_fidelity(const std::array<double, kTmqiScales>& s_local);
double tmqi_naturalness(const Plane& ldr);
double tmqi_combine(double s, double n);
// The published HDR stretch; a flat image (max == min) becomes all zero instead of NaN.
Plane tmqi_stretch_hdr(const Plane& hdr_luminance);

// From luminance planes: hdr linear (any scale), ldr on 0-255. Throws DataError for mismatched
// sizes or images smaller than kTmqiMinSize in either direction (the published code would
// return NaN there), and for non-finite HDR values.
TmqiResult tmqi(const Plane& hdr_luminance, const Plane& ldr_luminance);

// From interleaved RGB(A): hdr linear floats, ldr display-encoded on 0-255.
TmqiResult tmqi_rgb(const float* hdr, int hdr_channels, const float* ldr_255, int ldr_channels, int width, int height);

}  // namespace cgtmo::metrics
