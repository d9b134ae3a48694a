#pragma once
// SparseFactorization by UMFPACK: a sparse LU factorisation P (S A S) Q = L U of a general
// square A, with UMFPACK's own pivoting and iterative refinement but no further row scaling.
// Internal to sf_implicit: use make_factorization.
#include <memory>
#include <span>
#include <vector>

#include "implicit/sparse_factorization.hpp"

namespace sf {

class UmfpackFactorization final : public SparseFactorization {
 public:
  /// singular_pivot_ratio: see make_factorization.
  explicit UmfpackFactorization(double singular_pivot_ratio);
  ~UmfpackFactorization() override;
  UmfpackFactorization(const UmfpackFactorization&) = delete;
  UmfpackFactorization& operator=(const UmfpackFactorization&) = delete;

  void factorize(const CscMatrix& a) override;
  void solve(std::span<const double> b, std::span<double> x) override;

 private:
  struct Library;  ///< the UMFPACK objects (control, info, symbolic and numeric factors)
  /// The column of A of the smallest pivot |u_kk| (the first one in pivot order on a tie), or -1.
  int smallest_pivot_column();

  std::unique_ptr<Library> lib_;
  detail::ScaledSystem system_;
  std::vector<int> work_int_;        ///< umfpack_di_wsolve's Wi, n
  std::vector<double> work_double_;  ///< umfpack_di_wsolve's W, 5 n
  std::vector<double> solution_;     ///< the scaled solution, n
  std::vector<int> column_order_;    ///< pivot k -> column of A (umfpack_di_get_numeric's Q), n
  std::vector<double> pivots_;       ///< diagonal of U in pivot order, n
  double singular_pivot_ratio_;
  bool factorized_ = false;
};

}  // namespace sf
