// The sparse factorisations (src/implicit/sparse_factorization.hpp): CHOLMOD and UMFPACK against
// dense Eigen solves, the reuse of the symbolic analysis, the diagonal scaling, and the detection
// of singular and (CHOLMOD) indefinite matrices with the equation where they break down.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "implicit/sparse_factorization.hpp"

namespace sf {
namespace {

constexpr FactorizationMethod both_methods[] = {FactorizationMethod::cholmod,
                                                FactorizationMethod::umfpack};

/// A symmetric positive definite matrix with the pattern of a shell mesh: nx x ny nodes of 6
/// unknowns, each quad of 4 nodes adding a random SPD 24 x 24 block B^T B / 24 + 0.05 I, so
/// every node couples to its 3 x 3 neighbourhood.
CscMatrix shell_like_spd(int nx, int ny, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<CscTriplet> entries;
  for (int ey = 0; ey + 1 < ny; ++ey) {
    for (int ex = 0; ex + 1 < nx; ++ex) {
      const int nodes[4] = {ey * nx + ex, ey * nx + ex + 1, (ey + 1) * nx + ex + 1,
                            (ey + 1) * nx + ex};
      Eigen::MatrixXd b(24, 24);
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
  return csc_from_triplets(6 * nx * ny, entries);
}

/// The same pattern, made nonsymmetric: every off-diagonal entry times (1 + 0.3 u), u uniform in
/// [-1, 1].
CscMatrix nonsymmetric_version(CscMatrix a, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j < a.n; ++j) {
    for (int p = a.col_start[j]; p < a.col_start[j + 1]; ++p) {
      if (a.row_index[p] != j) {
        a.values[p] *= 1.0 + 0.3 * u(rng);
      }
    }
  }
  return a;
}

/// The 1-D Laplacian of n nodes (tridiagonal 2, -1), with the end diagonals `end` (1: free-free,
/// exactly singular; 2: held at both ends).
CscMatrix laplacian_1d(int n, double end) {
  std::vector<CscTriplet> entries;
  for (int i = 0; i < n; ++i) {
    entries.push_back({i, i, (i == 0 || i == n - 1) ? end : 2.0});
    if (i > 0) {
      entries.push_back({i, i - 1, -1.0});
      entries.push_back({i - 1, i, -1.0});
    }
  }
  return csc_from_triplets(n, entries);
}

std::span<const double> view(const Eigen::VectorXd& v) {
  return {v.data(), static_cast<std::size_t>(v.size())};
}
std::span<double> view(Eigen::VectorXd& v) {
  return {v.data(), static_cast<std::size_t>(v.size())};
}

Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) {
    v[i] = u(rng);
  }
  return v;
}

double relative_residual(const CscMatrix& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  Eigen::VectorXd ax(a.n);
  a.multiply(view(x), view(ax));
  return (ax - b).norm() / b.norm();
}

/// Solves with `f` (which must have factorised a) and checks against a dense LU solve.
Eigen::VectorXd solve_and_check(SparseFactorization& f, const CscMatrix& a, double residual,
                                unsigned seed) {
  const Eigen::VectorXd b = random_vector(a.n, seed);
  Eigen::VectorXd x(a.n);
  f.solve(view(b), view(x));
  EXPECT_LT(relative_residual(a, x, b), residual) << method_name(f.stats().method);
  const Eigen::VectorXd dense = a.to_dense().partialPivLu().solve(b);
  EXPECT_LT((x - dense).norm(), 1e-9 * dense.norm()) << method_name(f.stats().method);
  return x;
}

long lower_triangle_nonzeros(const CscMatrix& a) {
  long count = 0;
  for (int j = 0; j < a.n; ++j) {
    for (int p = a.col_start[j]; p < a.col_start[j + 1]; ++p) {
      count += a.row_index[p] >= j ? 1 : 0;
    }
  }
  return count;
}

/// The 0 x 0 matrix.
CscMatrix empty_matrix() {
  CscMatrix a;
  a.col_start = {0};
  return a;
}

template <class F>
SingularSystemError expect_singular(F&& f) {
  try {
    f();
  } catch (const SingularSystemError& e) {
    return e;
  }
  ADD_FAILURE() << "no SingularSystemError";
  return SingularSystemError("none", -2);
}

TEST(SparseFactorization, MethodNamesAndFactory) {
  EXPECT_STREQ(method_name(FactorizationMethod::cholmod), "CHOLMOD");
  EXPECT_STREQ(method_name(FactorizationMethod::umfpack), "UMFPACK");
  EXPECT_EQ(make_factorization(FactorizationMethod::cholmod)->stats().method,
            FactorizationMethod::cholmod);
  EXPECT_EQ(make_factorization(FactorizationMethod::umfpack)->stats().method,
            FactorizationMethod::umfpack);
  EXPECT_THROW(make_factorization(FactorizationMethod::cholmod, -1.0), std::invalid_argument);
  const SingularSystemError e("broke", 17);
  EXPECT_EQ(e.equation(), 17);
  EXPECT_STREQ(e.what(), "broke");
}

TEST(SparseFactorization, SpdShellPatternMatchesDenseSolve) {
  const CscMatrix a = shell_like_spd(6, 5, 1);  // 180 equations
  ASSERT_EQ(a.n, 180);
  ASSERT_LT(a.asymmetry(), 1e-15);
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto f = make_factorization(method);
    f->factorize(a);
    solve_and_check(*f, a, 1e-12, 2);
    const FactorizationStats& s = f->stats();
    EXPECT_EQ(s.method, method);
    EXPECT_EQ(s.equations, 180);
    EXPECT_EQ(s.matrix_nonzeros, a.nonzeros());
    EXPECT_EQ(s.analyses, 1);
    EXPECT_EQ(s.factorizations, 1);
    const long reference =
        method == FactorizationMethod::cholmod ? lower_triangle_nonzeros(a) : a.nonzeros();
    EXPECT_GE(s.factor_nonzeros, reference);
    EXPECT_DOUBLE_EQ(s.fill_ratio, static_cast<double>(s.factor_nonzeros) / reference);
    EXPECT_GE(s.fill_ratio, 1.0);
    EXPECT_GE(s.analyse_seconds, 0.0);
    EXPECT_GE(s.factor_seconds, 0.0);
    EXPECT_GE(s.solve_seconds, 0.0);
    EXPECT_GT(s.pivot_ratio, 1e-6);
    EXPECT_LE(s.pivot_ratio, 1.0);
  }
}

TEST(SparseFactorization, BothGiveTheSameSolutionAndCholmodCountsTheLowerFactor) {
  // A 2-D Laplacian + diagonal (5-point stencil, 12 x 12, one unknown per node). CHOLMOD's
  // factor can hold no fewer entries than a lower triangle; UMFPACK's L + U counts both.
  const int m = 12;
  std::vector<CscTriplet> entries;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < m; ++i) {
      const int k = j * m + i;
      entries.push_back({k, k, 4.5});
      if (i > 0) {
        entries.push_back({k, k - 1, -1.0});
        entries.push_back({k - 1, k, -1.0});
      }
      if (j > 0) {
        entries.push_back({k, k - m, -1.0});
        entries.push_back({k - m, k, -1.0});
      }
    }
  }
  const CscMatrix a = csc_from_triplets(m * m, entries);
  const auto cholmod = make_factorization(FactorizationMethod::cholmod);
  const auto umfpack = make_factorization(FactorizationMethod::umfpack);
  cholmod->factorize(a);
  umfpack->factorize(a);
  const Eigen::VectorXd x1 = solve_and_check(*cholmod, a, 1e-12, 3);
  const Eigen::VectorXd x2 = solve_and_check(*umfpack, a, 1e-12, 3);
  EXPECT_LT((x1 - x2).norm(), 1e-12 * x1.norm());
  EXPECT_GE(cholmod->stats().factor_nonzeros, lower_triangle_nonzeros(a));
  EXPECT_GE(umfpack->stats().factor_nonzeros, a.nonzeros());
}

TEST(SparseFactorization, UmfpackSolvesNonsymmetricMatrix) {
  const CscMatrix a = nonsymmetric_version(shell_like_spd(5, 5, 4), 5);
  ASSERT_GT(a.asymmetry(), 0.01);
  const auto f = make_factorization(FactorizationMethod::umfpack);
  f->factorize(a);
  solve_and_check(*f, a, 1e-12, 6);
  EXPECT_GE(f->stats().fill_ratio, 1.0);
}

TEST(SparseFactorization, CholmodReadsOnlyTheUpperTriangle) {
  const CscMatrix a = shell_like_spd(4, 4, 7);
  CscMatrix spoiled = a;  // garbage below the diagonal
  for (int j = 0; j < spoiled.n; ++j) {
    for (int p = spoiled.col_start[j]; p < spoiled.col_start[j + 1]; ++p) {
      if (spoiled.row_index[p] > j) {
        spoiled.values[p] = 1e3 * (p % 7 - 3);
      }
    }
  }
  const auto f = make_factorization(FactorizationMethod::cholmod);
  f->factorize(spoiled);
  solve_and_check(*f, a, 1e-12, 8);  // the solution of the symmetric matrix
}

TEST(SparseFactorization, SamePatternReusesTheAnalysisNewPatternRedoesIt) {
  const CscMatrix a = shell_like_spd(5, 4, 9);
  const CscMatrix a2 = shell_like_spd(5, 4, 10);  // same pattern, other values
  ASSERT_EQ(a2.row_index, a.row_index);
  const CscMatrix c = shell_like_spd(4, 5, 11);  // same size, other pattern
  ASSERT_EQ(c.n, a.n);
  ASSERT_NE(c.row_index, a.row_index);
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto f = make_factorization(method);
    f->factorize(a);
    solve_and_check(*f, a, 1e-12, 12);
    f->factorize(a2);
    EXPECT_EQ(f->stats().analyses, 1);
    EXPECT_EQ(f->stats().factorizations, 2);
    solve_and_check(*f, a2, 1e-12, 13);
    f->factorize(c);
    EXPECT_EQ(f->stats().analyses, 2);
    EXPECT_EQ(f->stats().factorizations, 3);
    solve_and_check(*f, c, 1e-12, 14);
    const CscMatrix small = laplacian_1d(7, 2.0);  // a new size
    f->factorize(small);
    EXPECT_EQ(f->stats().analyses, 3);
    EXPECT_EQ(f->stats().equations, 7);
    solve_and_check(*f, small, 1e-12, 15);
  }
}

TEST(SparseFactorization, SolveMayOverwriteItsRightHandSide) {
  const CscMatrix a = shell_like_spd(3, 3, 16);
  const Eigen::VectorXd b = random_vector(a.n, 17);
  for (const FactorizationMethod method : both_methods) {
    const auto f = make_factorization(method);
    f->factorize(a);
    Eigen::VectorXd x = b;
    f->solve(view(x), view(x));
    EXPECT_LT(relative_residual(a, x, b), 1e-12) << method_name(method);
  }
}

TEST(SparseFactorization, BadlyScaledUnknownsStillSolve) {
  // Rotational unknowns (3..5 of each node) in other units: D A D with D = 1e6 there, as if the
  // rotations were measured in micro-radians; the symmetric scaling removes it exactly.
  const CscMatrix a = shell_like_spd(5, 5, 18);
  std::vector<double> d(static_cast<std::size_t>(a.n));
  for (int i = 0; i < a.n; ++i) {
    d[i] = i % 6 >= 3 ? 1e6 : 1.0;
  }
  CscMatrix scaled = a;
  for (int j = 0; j < a.n; ++j) {
    for (int p = a.col_start[j]; p < a.col_start[j + 1]; ++p) {
      scaled.values[p] *= d[a.row_index[p]] * d[j];
    }
  }
  const Eigen::VectorXd b = random_vector(a.n, 19);
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto reference = make_factorization(method);
    reference->factorize(a);
    Eigen::VectorXd x(a.n);
    reference->solve(view(b), view(x));

    const auto f = make_factorization(method);
    f->factorize(scaled);
    // D A D y = D b  <=>  y = D^-1 x.
    Eigen::VectorXd db(a.n), y(a.n);
    for (int i = 0; i < a.n; ++i) {
      db[i] = d[i] * b[i];
    }
    f->solve(view(db), view(y));
    EXPECT_LT(relative_residual(scaled, y, db), 1e-10);
    Eigen::VectorXd recovered(a.n);
    for (int i = 0; i < a.n; ++i) {
      recovered[i] = d[i] * y[i];
    }
    EXPECT_LT((recovered - x).norm(), 1e-10 * x.norm());
    // The scaled matrix is the same after S A S: the same pivots.
    EXPECT_NEAR(f->stats().pivot_ratio, reference->stats().pivot_ratio,
                1e-10 * reference->stats().pivot_ratio);
  }
}

/// Grid sizes of the singularity tests: CHOLMOD factorises the 4 x 3 (72 equations) with a
/// simplicial L D L^T and the 10 x 10 (600 equations) with a supernodal L L^T; both must locate
/// the breakdown.
struct GridSize {
  int nx, ny;
};
constexpr GridSize simplicial_and_supernodal[] = {{4, 3}, {10, 10}};

/// a with row and column k set to 0 (pattern kept).
CscMatrix zero_row_and_column(CscMatrix a, int k) {
  for (int j = 0; j < a.n; ++j) {
    for (int p = a.col_start[j]; p < a.col_start[j + 1]; ++p) {
      if (j == k || a.row_index[p] == k) {
        a.values[p] = 0.0;
      }
    }
  }
  return a;
}

TEST(SparseFactorization, ZeroColumnIsSingularAtThatEquation) {
  for (const GridSize size : simplicial_and_supernodal) {
    const CscMatrix a = shell_like_spd(size.nx, size.ny, 20);
    for (const int zero : {0, 37, a.n / 2 + 1, a.n - 1}) {
      const CscMatrix z = zero_row_and_column(a, zero);
      for (const FactorizationMethod method : both_methods) {
        SCOPED_TRACE(std::string(method_name(method)) + ", " + std::to_string(a.n) +
                     " equations, column " + std::to_string(zero));
        const auto f = make_factorization(method);
        const SingularSystemError e = expect_singular([&] { f->factorize(z); });
        EXPECT_EQ(e.equation(), zero) << e.what();
        EXPECT_EQ(f->stats().pivot_ratio, 0.0);
        std::vector<double> b(static_cast<std::size_t>(z.n), 1.0), x(b.size());
        EXPECT_THROW(f->solve(b, x), std::logic_error);  // no usable factor
      }
    }
  }
}

TEST(SparseFactorization, FreeFreeLaplacianIsSingular) {
  // Exactly singular (the constant vector is its null space); in floating point the last pivot
  // is round-off, so the pivot ratio decides.
  const CscMatrix a = laplacian_1d(60, 1.0);
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto f = make_factorization(method);
    const SingularSystemError e = expect_singular([&] { f->factorize(a); });
    EXPECT_GE(e.equation(), 0) << e.what();
    EXPECT_LT(e.equation(), 60) << e.what();
    EXPECT_LT(f->stats().pivot_ratio, 1e-14);
    // Held at both ends it is fine: 2 on the end diagonals.
    f->factorize(laplacian_1d(60, 2.0));
    EXPECT_GT(f->stats().pivot_ratio, 1e-5);
    solve_and_check(*f, laplacian_1d(60, 2.0), 1e-12, 21);
  }
}

TEST(SparseFactorization, PivotRatioThresholdSeparatesIllConditionedFromSingular) {
  // [1, 1 - e; 1 - e, 1]: pivots 1 and 1 - (1 - e)^2 = 2e - e^2, ratio ~2e-9 for e = 1e-9.
  const double e = 1e-9;
  const CscMatrix a = csc_from_triplets(
      2, std::vector<CscTriplet>{{0, 0, 1.0}, {1, 0, 1.0 - e}, {0, 1, 1.0 - e}, {1, 1, 1.0}});
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto lenient = make_factorization(method);  // 1e-14
    lenient->factorize(a);
    EXPECT_NEAR(lenient->stats().pivot_ratio, 2e-9, 1e-15);
    const auto strict = make_factorization(method, 1e-8);
    const SingularSystemError error = expect_singular([&] { strict->factorize(a); });
    EXPECT_TRUE(error.equation() == 0 || error.equation() == 1) << error.what();
    EXPECT_NE(std::string(error.what()).find("pivot ratio"), std::string::npos) << error.what();
  }
}

TEST(SparseFactorization, CholmodRejectsIndefiniteMatrixAtTheNegativeEquation) {
  for (const GridSize size : simplicial_and_supernodal) {
    SCOPED_TRACE(std::to_string(size.nx) + " x " + std::to_string(size.ny) + " nodes");
    // An SPD shell block and, uncoupled, one equation with a negative diagonal: whatever the
    // ordering, the Cholesky factorisation breaks down there and only there.
    const int bad = size.nx == 4 ? 50 : 277;
    CscMatrix a = zero_row_and_column(shell_like_spd(size.nx, size.ny, 22), bad);
    a.values[a.find(bad, bad)] = -3.0;
    const auto cholmod = make_factorization(FactorizationMethod::cholmod);
    const SingularSystemError e = expect_singular([&] { cholmod->factorize(a); });
    EXPECT_EQ(e.equation(), bad) << e.what();
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
    // UMFPACK factorises the indefinite (nonsingular) matrix.
    const auto umfpack = make_factorization(FactorizationMethod::umfpack);
    umfpack->factorize(a);
    solve_and_check(*umfpack, a, 1e-12, 23);

    // A coupled indefinite matrix (the shell block minus 2 I): the breakdown is somewhere; after
    // it, the same pattern factorises again without a new analysis.
    const CscMatrix spd = shell_like_spd(size.nx, size.ny, 24);
    CscMatrix shifted = spd;
    for (int j = 0; j < shifted.n; ++j) {
      shifted.values[shifted.find(j, j)] -= 2.0;
    }
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(shifted.to_dense()).eigenvalues();
    ASSERT_LT(eigenvalues.minCoeff(), 0.0);
    ASSERT_GT(eigenvalues.maxCoeff(), 0.0);
    const auto f = make_factorization(FactorizationMethod::cholmod);
    const SingularSystemError coupled = expect_singular([&] { f->factorize(shifted); });
    EXPECT_GE(coupled.equation(), 0);
    EXPECT_LT(coupled.equation(), shifted.n);
    f->factorize(spd);
    EXPECT_EQ(f->stats().analyses, 1);
    EXPECT_EQ(f->stats().factorizations, 2);
    solve_and_check(*f, spd, 1e-12, 25);
  }
}

TEST(SparseFactorization, MisuseIsReported) {
  const CscMatrix a = shell_like_spd(3, 3, 26);
  for (const FactorizationMethod method : both_methods) {
    SCOPED_TRACE(method_name(method));
    const auto f = make_factorization(method);
    std::vector<double> b(a.n, 1.0), x(a.n);
    EXPECT_THROW(f->solve(b, x), std::logic_error);  // before any factorize
    CscMatrix broken = a;
    broken.row_index[3] = a.n;
    EXPECT_THROW(f->factorize(broken), std::invalid_argument);
    CscMatrix nan = a;
    nan.values[5] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(f->factorize(nan), std::invalid_argument);
    EXPECT_EQ(f->stats().factorizations, 0);
    f->factorize(a);
    std::vector<double> short_x(a.n - 1);
    EXPECT_THROW(f->solve(b, short_x), std::invalid_argument);
    // An empty system is trivially solved.
    f->factorize(empty_matrix());
    std::vector<double> none;
    EXPECT_NO_THROW(f->solve(none, none));
  }
}

}  // namespace
}  // namespace sf
