// Benchmark of the sparse factorisations of the implicit step (not a test): CHOLMOD and UMFPACK
// (src/implicit/sparse_factorization.hpp) on the same synthetic shell-like matrix, at about 10k,
// 40k and 100k equations. docs/static-linear-algebra.md records the figures.
//
// Matrix: an N x N grid of nodes with 6 unknowns each; every quad of 2 x 2 nodes adds a random
// symmetric positive definite 24 x 24 block B^T B / 24 + 0.05 I (B with standard normal entries,
// fixed seed), so each node couples to its 3 x 3-node neighbourhood, the pattern of a shell mesh
// of 4-node elements. Symmetric positive definite, well conditioned.
//
// Per size and method: equations, nnz(A) (full pattern), nnz(factor) and fill as in
// FactorizationStats, the seconds of the symbolic analysis, of the numeric factorisation (the
// faster of two with the same pattern, the second reusing the analysis) and of one solve, and
// the residual |A x - b| / |b| of that solve.
//
// Usage: bench_sparse_factorization [quick]   (quick: the 10k matrix only)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "implicit/sparse_factorization.hpp"

namespace {

sf::CscMatrix shell_like_matrix(int n_side, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<sf::CscTriplet> entries;
  entries.reserve(static_cast<std::size_t>(n_side - 1) * (n_side - 1) * 576);
  Eigen::MatrixXd b(24, 24);
  for (int ey = 0; ey + 1 < n_side; ++ey) {
    for (int ex = 0; ex + 1 < n_side; ++ex) {
      const int nodes[4] = {ey * n_side + ex, ey * n_side + ex + 1, (ey + 1) * n_side + ex + 1,
                            (ey + 1) * n_side + ex};
      for (int i = 0; i < b.size(); ++i) {
        b.data()[i] = normal(rng);
      }
      const Eigen::MatrixXd k = b.transpose() * b / 24.0 + 0.05 * Eigen::MatrixXd::Identity(24, 24);
      for (int c = 0; c < 24; ++c) {
        for (int r = 0; r < 24; ++r) {
          entries.push_back({6 * nodes[r / 6] + r % 6, 6 * nodes[c / 6] + c % 6, k(r, c)});
        }
      }
    }
  }
  return sf::csc_from_triplets(6 * n_side * n_side, entries);
}

struct Result {
  sf::FactorizationStats stats;
  double factor_seconds = 0.0;  ///< the faster of the two factorisations
  double residual = 0.0;
};

Result run(sf::FactorizationMethod method, const sf::CscMatrix& a) {
  const auto f = sf::make_factorization(method);
  f->factorize(a);
  double factor_seconds = f->stats().factor_seconds;
  f->factorize(a);  // same pattern: no new analysis
  factor_seconds = std::min(factor_seconds, f->stats().factor_seconds);
  std::vector<double> b(static_cast<std::size_t>(a.n)), x(b.size()), ax(b.size());
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& v : b) {
    v = u(rng);
  }
  f->solve(b, x);
  a.multiply(x, ax);
  double r2 = 0.0, b2 = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    r2 += (ax[i] - b[i]) * (ax[i] - b[i]);
    b2 += b[i] * b[i];
  }
  return {f->stats(), factor_seconds, std::sqrt(r2 / b2)};
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "quick") == 0;
  std::vector<int> sides = {41, 82, 129};  // 10086, 40344, 99846 equations
  if (quick) {
    sides.resize(1);
  }
  std::printf("%-8s %9s %10s %12s %6s %10s %10s %10s %9s %9s\n", "method", "equations", "nnz(A)",
              "nnz(factor)", "fill", "analyse_s", "factor_s", "solve_s", "residual", "analyses");
  for (const int side : sides) {
    const auto start = std::chrono::steady_clock::now();
    const sf::CscMatrix a = shell_like_matrix(side, 12345);
    const double build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const sf::FactorizationMethod method :
         {sf::FactorizationMethod::cholmod, sf::FactorizationMethod::umfpack}) {
      const Result r = run(method, a);
      std::printf("%-8s %9d %10ld %12ld %6.2f %10.3f %10.3f %10.4f %9.1e %9d\n",
                  sf::method_name(method), r.stats.equations, r.stats.matrix_nonzeros,
                  r.stats.factor_nonzeros, r.stats.fill_ratio, r.stats.analyse_seconds,
                  r.factor_seconds, r.stats.solve_seconds, r.residual, r.stats.analyses);
      std::fflush(stdout);
    }
    std::printf("(%d x %d nodes; matrix assembled in %.2f s)\n", side, side, build_seconds);
  }
  return 0;
}
