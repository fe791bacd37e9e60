#include "cgtmo/metrics/tmqi.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "cgtmo/color/luminance.h"
#include "cgtmo/errors.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::metrics {

namespace {

constexpr double kA = 0.8012, kAlpha = 0.3046, kBeta = 0.7088;
constexpr double kScaleWeights[kTmqiScales] = {0.0448, 0.2856, 0.3001, 0.2363, 0.1333};
constexpr double kC1 = 0.01, kC2 = 10.0;
constexpr double kWindowSigma = 1.5;
// Naturalness models fitted by the authors on 3000 natural images.
constexpr double kMeanMu = 115.94, kMeanSigma = 27.99;
constexpr double kStdA = 4.4, kStdB = 10.1, kStdScale = 64.29;

double normal_cdf(double x, double mu, double sigma) { return 0.5 * repro::erfc(-(x - mu) / (sigma * std::sqrt(2.0))); }

// The normalised 11x11 Gaussian is the outer product of this normalised 1-D one.
std::array<double, kTmqiWindow> gaussian_taps() {
  std::array<double, kTmqiWindow> g{};
  double sum = 0;
  for (int k = 0; k < kTmqiWindow; ++k) {
    const double d = k - kTmqiWindow / 2;
    g[k] = repro::exp(-d * d / (2 * kWindowSigma * kWindowSigma));
    sum += g[k];
  }
  for (double& v : g) v /= sum;
  return g;
}

// 2x2 mean with symmetric borders, then every other pixel from the first: ceil(n/2) per axis.
Plane downsample(const Plane& p) {
  Plane o;
  o.width = (p.width + 1) / 2;
  o.height = (p.height + 1) / 2;
  o.v.resize(std::size_t(o.width) * o.height);
  for (int y = 0; y < o.height; ++y) {
    const int y0 = 2 * y, y1 = std::min(2 * y + 1, p.height - 1);
    for (int x = 0; x < o.width; ++x) {
      const int x0 = 2 * x, x1 = std::min(2 * x + 1, p.width - 1);
      o.at(x, y) = 0.25 * (p.at(x0, y0) + p.at(x1, y0) + p.at(x0, y1) + p.at(x1, y1));
    }
  }
  return o;
}

}  // namespace

double tmqi_local_fidelity(const Plane& hdr, const Plane& ldr, double sf) {
  const int ow = hdr.width - (kTmqiWindow - 1), oh = hdr.height - (kTmqiWindow - 1);
  if (ow < 1 || oh < 1) throw DataError("TMQI: a scale of " + std::to_string(hdr.width) + "x" + std::to_string(hdr.height) +
                                        " px is smaller than the 11x11 window");
  const auto g = gaussian_taps();
  // Mannos-Sakrison CSF sets the threshold of visible local contrast at this frequency.
  const double csf = 100.0 * 2.6 * (0.0192 + 0.114 * sf) * repro::exp(-repro::pow(0.114 * sf, 1.1));
  const double u = 128.0 / (1.4 * csf), sig = u / 3.0;
  std::vector<double> row_sums(oh, 0.0);  // summed in row order: the same result on any thread count
  parallel_rows(oh, [&](int64_t b, int64_t e) {
    for (int64_t y = b; y < e; ++y) {
      double part = 0;
      for (int x = 0; x < ow; ++x) {
        // Moments about the window's centre value: the same statistics as the published
        // E[x^2] - E[x]^2, without its cancellation on the 2^32-stretched HDR values.
        const double c1 = hdr.at(x + 5, int(y) + 5), c2 = ldr.at(x + 5, int(y) + 5);
        double m1 = 0, m2 = 0, s11 = 0, s22 = 0, s12 = 0;
        for (int j = 0; j < kTmqiWindow; ++j) {
          const double* r1 = &hdr.v[std::size_t(y + j) * hdr.width + x];
          const double* r2 = &ldr.v[std::size_t(y + j) * ldr.width + x];
          for (int i = 0; i < kTmqiWindow; ++i) {
            const double w = g[j] * g[i];
            const double d1 = r1[i] - c1, d2 = r2[i] - c2;
            m1 += w * d1;
            m2 += w * d2;
            s11 += w * d1 * d1;
            s22 += w * d2 * d2;
            s12 += w * d1 * d2;
          }
        }
        const double sigma1 = std::sqrt(std::max(0.0, s11 - m1 * m1));
        const double sigma2 = std::sqrt(std::max(0.0, s22 - m2 * m2));
        const double sigma12 = s12 - m1 * m2;
        const double p1 = normal_cdf(sigma1, u, sig), p2 = normal_cdf(sigma2, u, sig);
        part += (2 * p1 * p2 + kC1) / (p1 * p1 + p2 * p2 + kC1) * ((sigma12 + kC2) / (sigma1 * sigma2 + kC2));
      }
      row_sums[y] = part;
    }
  });
  double total = 0;
  for (double v : row_sums) total += v;
  return total / (double(ow) * oh);
}

std::array<double, kTmqiScales> tmqi_fidelity_scales(Plane hdr, Plane ldr) {
  std::array<double, kTmqiScales> s{};
  double sf = 32;
  for (int l = 0; l < kTmqiScales; ++l) {
    sf /= 2;
    s[l] = tmqi_local_fidelity(hdr, ldr, sf);
    if (l + 1 < kTmqiScales) {
      hdr = downsample(hdr);
      ldr = downsample(ldr);
    }
  }
  return s;
}

double tmqi_structural_fidelity(const std::array<double, kTmqiScales>& s_local) {
  double s = 1;
  // A negative scale mean (structure inverted, e.g. an LDR anti-correlated with the HDR) would
  // make v1.0's S complex; it counts as no fidelity at that scale instead.
  for (int l = 0; l < kTmqiScales; ++l) s *= repro::pow(std::max(s_local[l], 0.0), kScaleWeights[l]);
  return s;
}

double tmqi_naturalness(const Plane& ldr) {
  const std::size_t n = ldr.v.size();
  double sum = 0;
  for (double v : ldr.v) sum += v;
  const double mean = sum / double(n);
  // Standard deviation (n-1) of each 11x11 block of the image padded with zeros to whole blocks,
  // spread over the block's pixels inside the image, then averaged over the image.
  double std_sum = 0;
  for (int by = 0; by < ldr.height; by += kTmqiWindow) {
    for (int bx = 0; bx < ldr.width; bx += kTmqiWindow) {
      const int ey = std::min(by + kTmqiWindow, ldr.height), ex = std::min(bx + kTmqiWindow, ldr.width);
      double s = 0, ss = 0;
      for (int y = by; y < ey; ++y)
        for (int x = bx; x < ex; ++x) s += ldr.at(x, y);
      const double k = double(kTmqiWindow * kTmqiWindow);
      const double bm = s / k;  // the padding zeros count in the block's mean
      for (int y = by; y < ey; ++y)
        for (int x = bx; x < ex; ++x) ss += (ldr.at(x, y) - bm) * (ldr.at(x, y) - bm);
      ss += (k - double(ey - by) * (ex - bx)) * bm * bm;
      std_sum += std::sqrt(ss / (k - 1)) * double(ey - by) * double(ex - bx);
    }
  }
  const double sigma = std_sum / double(n);
  // Ratios to each model's peak, so both factors are 1 at the most natural value.
  const double pb = repro::exp(-0.5 * (mean - kMeanMu) * (mean - kMeanMu) / (kMeanSigma * kMeanSigma));
  const double mode = (kStdA - 1) / (kStdA + kStdB - 2);
  const double x = sigma / kStdScale;
  const double pc = (x > 0 && x < 1) ? repro::pow(x / mode, kStdA - 1) * repro::pow((1 - x) / (1 - mode), kStdB - 1) : 0.0;
  return pb * pc;
}

double tmqi_combine(double s, double n) { return kA * repro::pow(s, kAlpha) + (1 - kA) * repro::pow(n, kBeta); }

Plane tmqi_stretch_hdr(const Plane& hdr) {
  Plane o = hdr;
  const auto [lo, hi] = std::minmax_element(hdr.v.begin(), hdr.v.end());
  const double lmin = *lo, range = *hi - *lo;
  if (!(range > 0)) {
    std::fill(o.v.begin(), o.v.end(), 0.0);
    return o;
  }
  const double factor = std::round((4294967296.0 - 1.0) / range);
  for (double& v : o.v) v = factor * (v - lmin);
  return o;
}

TmqiResult tmqi(const Plane& hdr_luminance, const Plane& ldr_luminance) {
  if (hdr_luminance.width != ldr_luminance.width || hdr_luminance.height != ldr_luminance.height)
    throw DataError("TMQI: HDR is " + std::to_string(hdr_luminance.width) + "x" + std::to_string(hdr_luminance.height) +
                    " but LDR is " + std::to_string(ldr_luminance.width) + "x" + std::to_string(ldr_luminance.height));
  if (hdr_luminance.width < kTmqiMinSize || hdr_luminance.height < kTmqiMinSize)
    throw DataError("TMQI: image is " + std::to_string(hdr_luminance.width) + "x" + std::to_string(hdr_luminance.height) +
                    ", needs at least " + std::to_string(kTmqiMinSize) + " px each way (5 scales of an 11x11 window)");
  for (double v : hdr_luminance.v)
    if (!std::isfinite(v)) throw DataError("TMQI: the HDR image holds non-finite luminance");
  TmqiResult r;
  r.s_local = tmqi_fidelity_scales(tmqi_stretch_hdr(hdr_luminance), ldr_luminance);
  r.s = tmqi_structural_fidelity(r.s_local);
  r.n = tmqi_naturalness(ldr_luminance);
  r.q = tmqi_combine(r.s, r.n);
  return r;
}

TmqiResult tmqi_rgb(const float* hdr, int hc, const float* ldr, int lc, int width, int height) {
  Plane h, l;
  h.width = l.width = width;
  h.height = l.height = height;
  const std::size_t n = std::size_t(width) * height;
  h.v.resize(n);
  l.v.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = hdr + i * hc;
    const float* q = ldr + i * lc;
    h.v[i] = color::luminance<double>(p[0], p[1], p[2]);
    l.v[i] = color::luminance<double>(q[0], q[1], q[2]);
  }
  return tmqi(h, l);
}

}  // namespace cgtmo::metrics
