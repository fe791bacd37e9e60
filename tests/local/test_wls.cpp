// WLS checked against its definition: the minimiser of the energy satisfies, at every pixel,
// (u_p - g_p) + lambda * sum_q a_pq (u_p - u_q) = 0 (its gradient, written out per pixel here),
// and simple cases whose answer is known without solving anything.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cgtmo/filters/wls.h"

using cgtmo::filters::WlsParams;

namespace {

// The filter over a plain buffer (and optional 0/1 mask), through the shared guide signature.
std::vector<float> wls_filter(const float* g, int w, int h, const WlsParams& p = {}, const unsigned char* mask = nullptr) {
  cgtmo::filters::GuidedInput in;
  in.width = w;
  in.height = h;
  in.log_lum = cgtmo::filters::Channel{g, 1};
  std::vector<float> m;
  if (mask) {
    m.assign(mask, mask + std::size_t(w) * h);
    in.mask = cgtmo::filters::Channel{m.data(), 1};
  }
  std::vector<float> out(std::size_t(w) * h);
  cgtmo::filters::wls_filter(in, p, out.data());
  return out;
}

// Largest |dE/du_p| / (1 + lambda sum_q a_pq) over the image: the energy's gradient from its
// definition, relative to the pixel's total weight (the output is float: the weights reach
// lambda / epsilon, so an absolute bound would measure float rounding).
double stationarity(const std::vector<float>& g, const std::vector<float>& u, int w, int h, const WlsParams& p,
                    const unsigned char* mask = nullptr) {
  double worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      if (mask && !mask[i]) continue;  // background is not an unknown
      double grad = double(u[i]) - g[i], weight = 1;
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
        const int j = ny[k] * w + nx[k];
        if (mask && mask[i] != mask[j]) continue;
        const double dl = std::abs(double(g[i]) - g[j]) * std::log(10.0);
        const double a = p.lambda / (std::pow(dl, p.alpha) + p.epsilon);
        grad += a * (double(u[i]) - u[j]);
        weight += a;
      }
      worst = std::max(worst, std::abs(grad) / weight);
    }
  return worst;
}

}  // namespace

TEST(Wls, ConstantImageIsUnchanged) {
  std::vector<float> g(37 * 23, 1.75f);
  const auto u = wls_filter(g.data(), 37, 23);
  for (float v : u) EXPECT_NEAR(v, 1.75f, 1e-5);
}

TEST(Wls, LambdaZeroIsTheIdentity) {
  std::vector<float> g = {0.f, 1.f, -2.f, 3.f, 0.5f, 0.25f};
  WlsParams p;
  p.lambda = 0;
  const auto u = wls_filter(g.data(), 3, 2, p);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NEAR(u[i], g[i], 1e-6);
}

TEST(Wls, SolutionIsTheEnergyMinimiser) {
  std::mt19937 rng(11);
  std::normal_distribution<float> n(0.f, 0.3f);
  const int w = 64, h = 48;
  std::vector<float> g(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) g[y * w + x] = (x < 30 ? 0.f : 2.f) + 0.02f * n(rng) + 0.005f * y;
  for (double lambda : {0.125, 1.0}) {
    WlsParams p;
    p.lambda = lambda;
    p.tolerance = 1e-10;
    const auto u = wls_filter(g.data(), w, h, p);
    EXPECT_LT(stationarity(g, u, w, h, p), 1e-6) << "lambda " << lambda;
  }
}

TEST(Wls, StrongEdgeIsPreservedNoiseIsSmoothed) {
  // Two flat halves 2 decades apart with small noise: the edge survives, the noise shrinks.
  std::mt19937 rng(5);
  std::normal_distribution<float> n(0.f, 0.01f);
  const int w = 40, h = 30;
  std::vector<float> g(w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) g[y * w + x] = (x < 20 ? 0.f : 2.f) + n(rng);
  WlsParams p;
  p.lambda = 1.0;
  const auto u = wls_filter(g.data(), w, h, p);
  double noise_in = 0, noise_out = 0;  // squared differences between vertical neighbours
  for (int y = 1; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      noise_in += std::pow(g[y * w + x] - g[(y - 1) * w + x], 2);
      noise_out += std::pow(u[y * w + x] - u[(y - 1) * w + x], 2);
    }
  EXPECT_LT(noise_out, 0.1 * noise_in);
  for (int y = 0; y < h; ++y) EXPECT_GT(u[y * w + 20] - u[y * w + 19], 1.9f);
}

TEST(Wls, MaskDecouplesRegionsAndKeepsBackground) {
  // Background (mask 0) keeps its input; the foreground never sees it.
  const int w = 20, h = 10;
  std::vector<float> g(w * h, 0.f);
  std::vector<unsigned char> mask(w * h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 5; ++x) {
      mask[y * w + x] = 0;
      g[y * w + x] = float(x + y) * 0.001f + 3.f;
    }
  WlsParams p;
  p.lambda = 1.0;
  p.tolerance = 1e-10;
  const auto u = wls_filter(g.data(), w, h, p, mask.data());
  double in = 0, out = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 5; ++x) {
      in += g[y * w + x];
      out += u[y * w + x];
    }
  EXPECT_EQ(out, in);  // background: base = input
  for (int y = 0; y < h; ++y)
    for (int x = 5; x < w; ++x) EXPECT_NEAR(u[y * w + x], 0.f, 1e-6);
  // The other way round the ramp is a foreground island: smoothed, its sum conserved (the
  // Laplacian's columns sum to zero), and the background keeps its zeros.
  for (auto& v : mask) v = 1 - v;
  const auto u2 = wls_filter(g.data(), w, h, p, mask.data());
  for (int y = 0; y < h; ++y)
    for (int x = 5; x < w; ++x) EXPECT_EQ(u2[y * w + x], 0.f);
  EXPECT_LT(stationarity(g, u2, w, h, p, mask.data()), 1e-6);
  double out2 = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 5; ++x) out2 += u2[y * w + x];
  EXPECT_NEAR(out2, in, 1e-3);
}

TEST(Wls, OnePixelAndOneRow) {
  const float one = 0.5f;
  EXPECT_NEAR(wls_filter(&one, 1, 1)[0], 0.5f, 1e-6);
  std::vector<float> row = {0.f, 0.1f, 0.2f, 5.f, 5.1f};
  const auto u = wls_filter(row.data(), 5, 1);
  for (float v : u) EXPECT_TRUE(std::isfinite(v));
}
