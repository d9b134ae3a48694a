#pragma once
// Sparse direct solution of A x = b for the implicit step: one interface over SuiteSparse's
// CHOLMOD (symmetric positive definite, Cholesky) and UMFPACK (general, LU), with a symmetric
// diagonal scaling, a singularity test on the pivots and timing statistics.
// docs/static-linear-algebra.md describes the choices.
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "implicit/csc_matrix.hpp"

namespace sf {

enum class FactorizationMethod { cholmod, umfpack };

/// "CHOLMOD" / "UMFPACK"
const char* method_name(FactorizationMethod m);

struct FactorizationStats {
  FactorizationMethod method = FactorizationMethod::cholmod;
  int equations = 0;
  long matrix_nonzeros = 0;  ///< stored entries of A (full pattern)
  long factor_nonzeros = 0;  ///< CHOLMOD: nnz(L); UMFPACK: nnz(L) + nnz(U) (diagonal once)
  /// factor_nonzeros over the entries of A the factor stands for: nnz(lower triangle of A incl.
  /// diagonal) for CHOLMOD, nnz(A) for UMFPACK. (CHOLMOD: counted as the stored entries on or
  /// above the diagonal, the ones it reads; the same number for a full symmetric pattern.)
  double fill_ratio = 0.0;
  double analyse_seconds = 0.0;  ///< s, the last symbolic analysis (fill-reducing ordering)
  double factor_seconds = 0.0;   ///< s, the last numeric factorisation
  double solve_seconds = 0.0;    ///< s, the last solve
  /// min |pivot| / max |pivot| of the last factorisation of the diagonally scaled matrix (CHOLMOD:
  /// cholmod_rcond; UMFPACK: Info[UMFPACK_RCOND]); 0 after a breakdown.
  double pivot_ratio = 0.0;
  int analyses = 0;        ///< symbolic analyses done so far
  int factorizations = 0;  ///< numeric factorisations done so far (failed ones included)
};

/// A factorisation that broke down: singular to working precision, or (CHOLMOD) not positive
/// definite.
class SingularSystemError : public std::runtime_error {
 public:
  SingularSystemError(const std::string& what, int equation);
  /// The equation (0-based column of A) where it broke down, or -1 when the library does not say.
  int equation() const { return equation_; }

 private:
  int equation_ = -1;
};

/// A sparse direct solver for A x = b. Before factorising, A is scaled symmetrically, S A S with
/// S = diag(1/sqrt|a_ii|) (1 where a_ii = 0), so that the pivot ratio means the same for
/// translational and rotational unknowns; solve() undoes the scaling.
class SparseFactorization {
 public:
  virtual ~SparseFactorization() = default;
  /// Factorises A. The symbolic analysis is redone only when the pattern (n, col_start,
  /// row_index) differs from the last one. CHOLMOD reads only the upper triangle of A (A must be
  /// symmetric). Throws SingularSystemError when the factorisation breaks down or pivot_ratio <
  /// the singular_pivot_ratio given at construction; std::invalid_argument for a malformed matrix
  /// (structure, or a value that is not finite). After a throw, solve() refuses until the next
  /// successful factorize. With an unchanged pattern, allocates nothing of its own (the library
  /// allocates its numeric factor).
  virtual void factorize(const CscMatrix& a) = 0;
  /// x = A^-1 b with the last factorisation (sizes n; b and x may be the same array). Throws
  /// std::logic_error before any factorize (or after a failed one), std::invalid_argument on a
  /// size mismatch. Allocates nothing after the first call.
  virtual void solve(std::span<const double> b, std::span<double> x) = 0;
  const FactorizationStats& stats() const { return stats_; }

 protected:
  FactorizationStats stats_;
};

/// singular_pivot_ratio: below it the matrix is declared singular (default 1e-14: exact or
/// round-off singularity, not mere ill-conditioning). Throws std::invalid_argument when it is
/// negative or not finite.
std::unique_ptr<SparseFactorization> make_factorization(FactorizationMethod method,
                                                        double singular_pivot_ratio = 1e-14);

namespace detail {

/// The part of the work that both solvers share: the pattern kept for comparison, the scaling,
/// the scaled values and work vectors. Internal to sf_implicit.
class ScaledSystem {
 public:
  /// Validates A (structure, finite values). Returns true when its pattern differs from the one
  /// kept (then keeps the new one and sizes the work arrays).
  bool update_pattern(const CscMatrix& a);
  /// scale = 1/sqrt|a_ii| (1 where a_ii = 0 or absent); scaled values s_i a_ij s_j.
  void scale_values(const CscMatrix& a);

  int n() const { return n_; }
  const std::vector<int>& col_start() const { return col_start_; }
  const std::vector<int>& row_index() const { return row_index_; }
  const std::vector<int>& diagonal() const { return diagonal_; }
  const std::vector<double>& scale() const { return scale_; }
  const std::vector<double>& scaled_values() const { return scaled_; }
  std::vector<double>& rhs() { return rhs_; }  ///< work vector of size n
  /// Number of stored entries with row <= col.
  long upper_nonzeros() const { return upper_nonzeros_; }

 private:
  int n_ = -1;
  std::vector<int> col_start_, row_index_;
  std::vector<int> diagonal_;  ///< position of a_jj in row_index, or -1
  std::vector<double> scale_;
  std::vector<double> scaled_;
  std::vector<double> rhs_;
  long upper_nonzeros_ = 0;
};

/// Seconds since `start` on the steady clock.
double seconds_since(long long start_ns);
/// The steady clock now, ns.
long long clock_ns();

}  // namespace detail

}  // namespace sf
