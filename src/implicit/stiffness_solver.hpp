#pragma once
// Chooses and runs the sparse direct solver of a static step: CHOLMOD for a symmetric positive
// definite tangent, UMFPACK for one that is not symmetric (or not positive definite), as the
// case's implicit.linear_solver asks. Accumulates the factorisation times and keeps the fill.
#include <memory>
#include <span>

#include "casefile/case_config.hpp"
#include "implicit/csc_matrix.hpp"
#include "implicit/sparse_factorization.hpp"

namespace sf {

/// Relative asymmetry max|K - K^T| / max|K| below which "auto" treats a finite-difference tangent
/// as symmetric (its differences are accurate to about 1e-9 relative; the corotational stress
/// terms of a stressed shell are not symmetric, at about sigma / E ~ 1e-3).
inline constexpr double kSymmetryTolerance = 1e-6;

struct StiffnessSolverTotals {
  double analyse_seconds = 0.0;
  double factor_seconds = 0.0;
  double solve_seconds = 0.0;
  int factorizations = 0;
  int cholmod_factorizations = 0;
  int umfpack_factorizations = 0;
  double max_asymmetry = 0.0;  ///< largest relative asymmetry of the tangents factorised
};

class StiffnessSolver {
 public:
  explicit StiffnessSolver(ImplicitConfig::LinearSolver choice);

  /// Factorises k (symmetrised in place when CHOLMOD takes it). Throws SingularSystemError when
  /// the chosen solver finds k singular (with "auto", a tangent CHOLMOD finds not positive
  /// definite goes to UMFPACK first).
  void factorize(CscMatrix& k);
  /// x = K^-1 b with the last factorisation.
  void solve(std::span<const double> b, std::span<double> x);

  /// The statistics of the last factorisation (method, fill, times).
  const FactorizationStats& last_stats() const;
  const StiffnessSolverTotals& totals() const { return totals_; }

 private:
  void account(const SparseFactorization& f, int analyses_before);

  ImplicitConfig::LinearSolver choice_;
  std::unique_ptr<SparseFactorization> cholmod_;
  std::unique_ptr<SparseFactorization> umfpack_;
  SparseFactorization* last_ = nullptr;
  StiffnessSolverTotals totals_;
};

}  // namespace sf
