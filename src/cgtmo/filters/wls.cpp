#include "cgtmo/filters/wls.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <cmath>

#include "cgtmo/errors.h"

namespace cgtmo::filters {

std::vector<float> wls_filter(const float* g, int w, int h, const WlsParams& p, const unsigned char* mask, WlsReport* report) {
  if (w <= 0 || h <= 0) throw UsageError("wls: empty image");
  const std::size_t n = std::size_t(w) * h;
  const Eigen::Index N = Eigen::Index(n);
  constexpr double kLn10 = 2.302585092994046;
  // Affinity between a pixel and its right/lower neighbour (0 across the mask boundary).
  auto affinity = [&](std::size_t a, std::size_t b) -> double {
    if (mask && mask[a] != mask[b]) return 0.0;
    const double d = std::abs(double(g[a]) - double(g[b])) * kLn10;  // natural-log guide
    return p.lambda / (std::pow(d, p.alpha) + p.epsilon);
  };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(n * 5);
  Eigen::VectorXd diag = Eigen::VectorXd::Ones(N);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (x + 1 < w) {
        const double a = affinity(i, i + 1);
        t.emplace_back(Eigen::Index(i), Eigen::Index(i + 1), -a);
        t.emplace_back(Eigen::Index(i + 1), Eigen::Index(i), -a);
        diag[Eigen::Index(i)] += a;
        diag[Eigen::Index(i + 1)] += a;
      }
      if (y + 1 < h) {
        const double a = affinity(i, i + w);
        t.emplace_back(Eigen::Index(i), Eigen::Index(i + w), -a);
        t.emplace_back(Eigen::Index(i + w), Eigen::Index(i), -a);
        diag[Eigen::Index(i)] += a;
        diag[Eigen::Index(i + w)] += a;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) t.emplace_back(Eigen::Index(i), Eigen::Index(i), diag[Eigen::Index(i)]);
  Eigen::SparseMatrix<double> A(N, N);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd b(N);
  for (std::size_t i = 0; i < n; ++i) b[Eigen::Index(i)] = g[i];

  // The matrix is diagonally dominant (I + Laplacian): CG with an incomplete Cholesky
  // preconditioner converges in a few dozen iterations.
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg;
  cg.setTolerance(p.tolerance);
  cg.setMaxIterations(p.max_iterations);
  cg.compute(A);
  if (cg.info() != Eigen::Success) throw DataError("wls: preconditioner failed to factor the system");
  Eigen::VectorXd u = cg.solveWithGuess(b, b);
  if (report) {
    report->iterations = int(cg.iterations());
    report->residual = cg.error();
  }
  std::vector<float> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = float(u[Eigen::Index(i)]);
  return out;
}

}  // namespace cgtmo::filters
