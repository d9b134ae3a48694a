#pragma once
// SparseFactorization by CHOLMOD: a sparse Cholesky factorisation P (S A S) P^T = L L^T (or
// L D L^T for small simplicial factors) of a symmetric positive definite A, upper triangle read.
// Internal to sf_implicit: use make_factorization.
#include <memory>
#include <span>

#include "implicit/sparse_factorization.hpp"

namespace sf {

class CholmodFactorization final : public SparseFactorization {
 public:
  /// singular_pivot_ratio: see make_factorization.
  explicit CholmodFactorization(double singular_pivot_ratio);
  ~CholmodFactorization() override;
  CholmodFactorization(const CholmodFactorization&) = delete;
  CholmodFactorization& operator=(const CholmodFactorization&) = delete;

  void factorize(const CscMatrix& a) override;
  void solve(std::span<const double> b, std::span<double> x) override;

 private:
  struct Library;  ///< the CHOLMOD objects (cholmod_common, matrix, factor, solve workspace)
  void analyse();
  /// After a numeric factorisation: throws SingularSystemError on a breakdown or a pivot ratio
  /// below the threshold.
  void check_pivots();

  std::unique_ptr<Library> lib_;
  detail::ScaledSystem system_;
  std::vector<int>
      upper_source_;  ///< for each entry of CHOLMOD's upper triangle, its position in A
  double singular_pivot_ratio_;
  bool factorized_ = false;
};

}  // namespace sf
