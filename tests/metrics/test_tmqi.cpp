// TMQI checked against values derived from the published definition, not from our code:
// closed forms for S and N on constructed images, and a second, separable formulation of the
// local statistics (E[x^2] - E[x]^2 with the 2-D window split in two 1-D passes, as MATLAB's
// filter2(..., 'valid') computes them) on values small enough that it is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cgtmo/errors.h"
#include "cgtmo/metrics/tmqi.h"

using namespace cgtmo::metrics;

namespace {

Plane make(int w, int h, double v = 0) {
  Plane p;
  p.width = w;
  p.height = h;
  p.v.assign(std::size_t(w) * h, v);
  return p;
}

// Standard normal CDF at -3: both contrast probabilities of a flat window.
constexpr double kPhiMinus3 = 0.0013498980316300946;
constexpr double kWeightSum = 0.0448 + 0.2856 + 0.3001 + 0.2363 + 0.1333;  // 1.0001 as published

// A checkerboard of `cell`-px squares, values lo/hi: cells aligned to multiples of 32 survive
// the four 2x2 decimations unchanged (a 2-px checker at the fifth scale).
Plane checker(int w, int h, int cell, double lo, double hi) {
  Plane p = make(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) p.at(x, y) = ((x / cell + y / cell) % 2) ? hi : lo;
  return p;
}

// 11x11 blocks whose values are mean +- d (60 each) and one mean: each block's sample standard
// deviation (n-1) is exactly d, the image mean exactly `mean`.
Plane blocks_with_std(int nbx, int nby, double mean, double d) {
  Plane p = make(11 * nbx, 11 * nby);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const int k = (y % 11) * 11 + (x % 11);
      p.at(x, y) = k == 120 ? mean : mean + ((k % 2) ? d : -d);
    }
  return p;
}

}  // namespace

TEST(Tmqi, FlatLdrAgainstTexturedHdrGivesTheClosedForm) {
  // HDR random at every scale -> its stretched local std is enormous -> p_hdr = 1 everywhere;
  // a flat LDR has sigma2 = sigma12 = 0 -> p_ldr = Phi(-3) and the second factor is 10/10.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.01, 100.0);
  Plane hdr = make(209, 198);  // whole 11x11 blocks: no zero padding in N
  for (double& v : hdr.v) v = u(rng);
  const Plane ldr = make(209, 198, 128.0);
  const double per_window = (2 * kPhiMinus3 + 0.01) / (1 + kPhiMinus3 * kPhiMinus3 + 0.01);
  const TmqiResult r = tmqi(hdr, ldr);
  for (double s : r.s_local) EXPECT_NEAR(s, per_window, 1e-12);
  EXPECT_NEAR(r.s, std::pow(per_window, kWeightSum), 1e-12);
  EXPECT_DOUBLE_EQ(r.n, 0.0);  // zero contrast: Beta pdf at 0
  EXPECT_NEAR(r.q, 0.8012 * std::pow(r.s, 0.3046), 1e-12);
}

TEST(Tmqi, LdrProportionalToHdrHasFullFidelity) {
  // LDR = 255 * HDR / max with strong edges at every scale: sigma12 = sigma1 sigma2 and both
  // contrast probabilities are 1 at edges and Phi(-3) in flat windows: every term is 1.
  const Plane hdr = checker(256, 192, 32, 0.05, 3000.0);
  Plane ldr = hdr;
  for (double& v : ldr.v) v = 255.0 * v / 3000.0;
  const TmqiResult r = tmqi(hdr, ldr);
  for (double s : r.s_local) EXPECT_NEAR(s, 1.0, 1e-6);
  EXPECT_NEAR(r.s, 1.0, 1e-6);
  // ... and the HDR's absolute scale does not matter (it is stretched to 2^32 first).
  Plane hdr2 = hdr;
  for (double& v : hdr2.v) v *= 1e-3;
  EXPECT_NEAR(tmqi(hdr2, ldr).s, r.s, 1e-9);
}

TEST(Tmqi, InvertedLdrLosesStructure) {
  // LDR = 255 - a HDR: sigma12 = -sigma1 sigma2, so edge windows score (10 - s1s2)/(s1s2 + 10) < 0.
  const Plane hdr = checker(256, 192, 32, 0.0, 1.0);
  Plane ldr = hdr;
  for (double& v : ldr.v) v = 255.0 * (1.0 - v);
  const TmqiResult r = tmqi(hdr, ldr);
  EXPECT_LT(r.s_local[0], 0.9);
  EXPECT_TRUE(std::isfinite(r.q));
}

TEST(Tmqi, NegativeScaleFidelityCountsAsZero) {
  // Uncorrelated noise can average below 0 at a scale: S is then 0 (v1.0 would go complex).
  EXPECT_DOUBLE_EQ(tmqi_structural_fidelity({0.9, -0.01, 0.9, 0.9, 0.9}), 0.0);
  EXPECT_NEAR(tmqi_structural_fidelity({0.5, 0.5, 0.5, 0.5, 0.5}), std::pow(0.5, kWeightSum), 1e-15);
}

TEST(Tmqi, NaturalnessIsOneAtBothModelPeaks) {
  // Mean at the Gaussian's peak 115.94; block std at the Beta mode (a-1)/(a+b-2) * 64.29.
  const double mode_std = (4.4 - 1) / (4.4 + 10.1 - 2) * 64.29;
  EXPECT_NEAR(tmqi_naturalness(blocks_with_std(10, 9, 115.94, mode_std)), 1.0, 1e-12);
}

TEST(Tmqi, NaturalnessFactorsByHand) {
  const double mode = 3.4 / 12.5;
  const double mode_std = mode * 64.29;
  // One model standard deviation above the mean: exp(-1/2).
  EXPECT_NEAR(tmqi_naturalness(blocks_with_std(10, 9, 115.94 + 27.99, mode_std)), std::exp(-0.5), 1e-12);
  // Contrast at x = 0.5 of the Beta(4.4, 10.1): (x/m)^3.4 ((1-x)/(1-m))^9.1.
  const double pc = std::pow(0.5 / mode, 3.4) * std::pow(0.5 / (1 - mode), 9.1);
  EXPECT_NEAR(tmqi_naturalness(blocks_with_std(10, 9, 115.94, 0.5 * 64.29)), pc, 1e-12);
}

TEST(Tmqi, NaturalnessCountsZeroPaddingOfPartialBlocks) {
  // 12x11 image of constant 100: block 1 is flat (std 0); block 2 holds one column of 100 and
  // 110 padding zeros: std = sqrt(11*100^2*(1 - 11/121)/120), spread over its 11 real pixels.
  Plane p = make(12, 11, 100.0);
  const double m = 1100.0 / 121.0;
  const double ss = 11 * (100 - m) * (100 - m) + 110 * m * m;
  const double sigma = std::sqrt(ss / 120.0) * 11.0 / 132.0;
  const double x = sigma / 64.29, mode = 3.4 / 12.5;
  const double pc = std::pow(x / mode, 3.4) * std::pow((1 - x) / (1 - mode), 9.1);
  const double pb = std::exp(-0.5 * std::pow((100 - 115.94) / 27.99, 2));
  EXPECT_NEAR(tmqi_naturalness(p), pb * pc, 1e-12);
}

TEST(Tmqi, LocalFidelityMatchesTheSeparableFormulation) {
  // Small-valued random images (no cancellation), 'valid' output, Gaussian 11x11 sigma 1.5.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 8.0);
  Plane a = make(40, 31), b = make(40, 31);
  for (double& v : a.v) v = u(rng);
  for (double& v : b.v) v = u(rng) + 0.5 * v;  // partly correlated
  std::vector<double> g(11);
  double gs = 0;
  for (int k = 0; k < 11; ++k) gs += g[k] = std::exp(-(k - 5) * (k - 5) / 4.5);
  for (double& v : g) v /= gs;
  auto valid = [&](const std::vector<double>& img) {  // rows then columns
    const int w = 40, h = 31, ow = 30, oh = 21;
    std::vector<double> tmp(std::size_t(h) * ow), out(std::size_t(oh) * ow);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < ow; ++x) {
        double s = 0;
        for (int k = 0; k < 11; ++k) s += g[k] * img[std::size_t(y) * w + x + k];
        tmp[std::size_t(y) * ow + x] = s;
      }
    for (int y = 0; y < oh; ++y)
      for (int x = 0; x < ow; ++x) {
        double s = 0;
        for (int k = 0; k < 11; ++k) s += g[k] * tmp[std::size_t(y + k) * ow + x];
        out[std::size_t(y) * ow + x] = s;
      }
    return out;
  };
  std::vector<double> aa(a.v.size()), bb(a.v.size()), ab(a.v.size());
  for (std::size_t i = 0; i < a.v.size(); ++i) {
    aa[i] = a.v[i] * a.v[i];
    bb[i] = b.v[i] * b.v[i];
    ab[i] = a.v[i] * b.v[i];
  }
  const auto mu1 = valid(a.v), mu2 = valid(b.v), e11 = valid(aa), e22 = valid(bb), e12 = valid(ab);
  for (double sf : {16.0, 1.0}) {
    const double csf = 100.0 * 2.6 * (0.0192 + 0.114 * sf) * std::exp(-std::pow(0.114 * sf, 1.1));
    const double uu = 128 / (1.4 * csf), sg = uu / 3;
    auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - uu) / (sg * std::sqrt(2.0))); };
    double sum = 0;
    for (std::size_t i = 0; i < mu1.size(); ++i) {
      const double s1 = std::sqrt(std::max(0.0, e11[i] - mu1[i] * mu1[i]));
      const double s2 = std::sqrt(std::max(0.0, e22[i] - mu2[i] * mu2[i]));
      const double s12 = e12[i] - mu1[i] * mu2[i];
      const double p1 = cdf(s1), p2 = cdf(s2);
      sum += (2 * p1 * p2 + 0.01) / (p1 * p1 + p2 * p2 + 0.01) * (s12 + 10) / (s1 * s2 + 10);
    }
    EXPECT_NEAR(tmqi_local_fidelity(a, b, sf), sum / double(mu1.size()), 1e-10) << "sf " << sf;
  }
}

TEST(Tmqi, CombinationFormula) {
  EXPECT_NEAR(tmqi_combine(1.0, 1.0), 1.0, 1e-15);
  EXPECT_NEAR(tmqi_combine(0.5, 0.25), 0.8012 * std::pow(0.5, 0.3046) + 0.1988 * std::pow(0.25, 0.7088), 1e-15);
}

TEST(Tmqi, RejectsWhatThePublishedCodeCannotScore) {
  EXPECT_THROW(tmqi(make(200, 200), make(200, 199)), cgtmo::DataError);
  EXPECT_THROW(tmqi(make(160, 300), make(160, 300)), cgtmo::DataError);  // fifth scale < 11 px
  Plane bad = make(200, 200, 1.0);
  bad.v[5] = std::nan("");
  EXPECT_THROW(tmqi(bad, make(200, 200)), cgtmo::DataError);
}

TEST(Tmqi, FlatHdrIsFiniteAndSmallestSizeWorks) {
  const TmqiResult r = tmqi(make(kTmqiMinSize, kTmqiMinSize, 5.0), make(kTmqiMinSize, kTmqiMinSize, 115.94));
  EXPECT_TRUE(std::isfinite(r.q));
  EXPECT_NEAR(r.s, 1.0, 1e-12);  // both flat: every window scores 1
}
