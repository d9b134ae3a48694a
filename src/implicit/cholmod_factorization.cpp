#include "implicit/cholmod_factorization.hpp"

#include <cholmod.h>
#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

namespace sf {

// The CHOLMOD objects, owned: cholmod_finish runs after everything allocated with the common
// object has been freed with it.
struct CholmodFactorization::Library {
  cholmod_common common{};
  cholmod_sparse* matrix = nullptr;  ///< the upper triangle of S A S (stype 1)
  cholmod_factor* factor = nullptr;
  cholmod_dense* solution = nullptr;  ///< cholmod_solve2's X, kept between solves
  cholmod_dense* work_y = nullptr;    ///< cholmod_solve2's workspace, kept between solves
  cholmod_dense* work_e = nullptr;

  Library() {
    cholmod_start(&common);
    common.print = 0;  // nothing on stdout or stderr: failures come back as exceptions
    common.error_handler = nullptr;
  }
  ~Library() {
    free_solve_workspace();
    free_factor();
    free_matrix();
    cholmod_finish(&common);
  }
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;

  void free_matrix() {
    if (matrix != nullptr) {
      cholmod_free_sparse(&matrix, &common);
    }
  }
  void free_factor() {
    if (factor != nullptr) {
      cholmod_free_factor(&factor, &common);
    }
  }
  void free_solve_workspace() {
    for (cholmod_dense** d : {&solution, &work_y, &work_e}) {
      if (*d != nullptr) {
        cholmod_free_dense(d, &common);
      }
    }
  }
  /// Throws for a CHOLMOD error (a negative status); warnings are the caller's business.
  void check(const char* call) const {
    if (common.status == CHOLMOD_OUT_OF_MEMORY) {
      throw std::bad_alloc();
    }
    if (common.status < 0) {
      throw std::runtime_error(
          fmt::format("CHOLMOD: {} failed with status {}", call, common.status));
    }
  }
};

CholmodFactorization::CholmodFactorization(double singular_pivot_ratio)
    : lib_(std::make_unique<Library>()), singular_pivot_ratio_(singular_pivot_ratio) {
  stats_.method = FactorizationMethod::cholmod;
}

CholmodFactorization::~CholmodFactorization() = default;

void CholmodFactorization::analyse() {
  Library& lib = *lib_;
  lib.free_solve_workspace();
  lib.free_factor();
  lib.free_matrix();
  const int n = system_.n();
  const std::vector<int>& col_start = system_.col_start();
  const std::vector<int>& row_index = system_.row_index();
  // CHOLMOD's copy of A: the entries on or above the diagonal, in A's order.
  upper_source_.clear();
  upper_source_.reserve(static_cast<std::size_t>(system_.upper_nonzeros()));
  lib.matrix =
      cholmod_allocate_sparse(static_cast<std::size_t>(n), static_cast<std::size_t>(n),
                              static_cast<std::size_t>(system_.upper_nonzeros()),
                              /*sorted=*/1, /*packed=*/1, /*stype=*/1, CHOLMOD_REAL, &lib.common);
  lib.check("cholmod_allocate_sparse");
  int* ap = static_cast<int*>(lib.matrix->p);
  int* ai = static_cast<int*>(lib.matrix->i);
  ap[0] = 0;
  for (int j = 0; j < n; ++j) {
    for (int p = col_start[j]; p < col_start[j + 1] && row_index[p] <= j; ++p) {
      ai[upper_source_.size()] = row_index[p];
      upper_source_.push_back(p);
    }
    ap[j + 1] = static_cast<int>(upper_source_.size());
  }
  const long long start = detail::clock_ns();
  lib.factor = cholmod_analyze(lib.matrix, &lib.common);
  stats_.analyse_seconds = detail::seconds_since(start);
  lib.check("cholmod_analyze");
  ++stats_.analyses;
  stats_.equations = n;
  // Common.lnz: nnz(L) of the chosen ordering, without the zeros that supernodal amalgamation
  // adds.
  stats_.factor_nonzeros = static_cast<long>(lib.common.lnz);
  stats_.fill_ratio = system_.upper_nonzeros() > 0
                          ? static_cast<double>(stats_.factor_nonzeros) /
                                static_cast<double>(system_.upper_nonzeros())
                          : 0.0;
}

void CholmodFactorization::factorize(const CscMatrix& a) {
  factorized_ = false;
  Library& lib = *lib_;
  if (system_.update_pattern(a) || lib.factor == nullptr) {
    analyse();
  }
  stats_.matrix_nonzeros = a.nonzeros();
  system_.scale_values(a);
  const std::vector<double>& scaled = system_.scaled_values();
  double* ax = static_cast<double*>(lib.matrix->x);
  for (std::size_t q = 0; q < upper_source_.size(); ++q) {
    ax[q] = scaled[upper_source_[q]];
  }
  const long long start = detail::clock_ns();
  cholmod_factorize(lib.matrix, lib.factor, &lib.common);
  stats_.factor_seconds = detail::seconds_since(start);
  ++stats_.factorizations;
  lib.check("cholmod_factorize");
  check_pivots();
  factorized_ = true;
}

void CholmodFactorization::check_pivots() {
  Library& lib = *lib_;
  const cholmod_factor& l = *lib.factor;
  const int n = system_.n();
  const int* perm = static_cast<const int*>(l.Perm);
  if (lib.common.status == CHOLMOD_NOT_POSDEF || l.minor < l.n) {
    stats_.pivot_ratio = 0.0;
    const int k = static_cast<int>(l.minor);
    const int equation = k < n ? perm[k] : -1;
    throw SingularSystemError(
        fmt::format("CHOLMOD: the matrix is not positive definite: the Cholesky factorisation "
                    "breaks down at equation {} (pivot {} of {})",
                    equation, k + 1, n),
        equation);
  }
  // The pivots d_k (L_kk^2 for L L^T, D_kk for L D L^T) in elimination order. A simplicial
  // L D L^T goes on through negative pivots, so look for the first non-positive one here; and
  // note the smallest, to name the equation when the ratio is too small.
  const double* lx = static_cast<const double*>(l.x);
  int first_nonpositive = -1;
  int smallest = -1;
  double smallest_pivot = std::numeric_limits<double>::infinity();
  auto visit = [&](int k, double d) {
    if (!(d > 0.0) && first_nonpositive < 0) {
      first_nonpositive = k;
    }
    if (std::abs(d) < smallest_pivot) {
      smallest_pivot = std::abs(d);
      smallest = k;
    }
  };
  if (l.is_super) {
    const int* super = static_cast<const int*>(l.super);
    const int* pi = static_cast<const int*>(l.pi);
    const int* px = static_cast<const int*>(l.px);
    for (std::size_t s = 0; s < l.nsuper; ++s) {
      const int rows = pi[s + 1] - pi[s];
      for (int k = super[s]; k < super[s + 1]; ++k) {
        const int local = k - super[s];
        const double lkk = lx[px[s] + local + static_cast<std::ptrdiff_t>(local) * rows];
        visit(k, lkk * lkk);
      }
    }
  } else {
    const int* lp = static_cast<const int*>(l.p);
    for (int k = 0; k < n; ++k) {
      const double lkk = lx[lp[k]];
      visit(k, l.is_ll ? lkk * lkk : lkk);
    }
  }
  if (first_nonpositive >= 0) {
    stats_.pivot_ratio = 0.0;
    const int equation = perm[first_nonpositive];
    throw SingularSystemError(
        fmt::format("CHOLMOD: the matrix is not positive definite: pivot {} of {} (equation {}) "
                    "is not positive",
                    first_nonpositive + 1, n, equation),
        equation);
  }
  stats_.pivot_ratio = n > 0 ? cholmod_rcond(lib.factor, &lib.common) : 1.0;
  if (!(stats_.pivot_ratio >= singular_pivot_ratio_)) {
    const int equation = smallest >= 0 ? perm[smallest] : -1;
    throw SingularSystemError(
        fmt::format("CHOLMOD: the matrix is singular to working precision: pivot ratio {:.3g} "
                    "below {:.3g}, smallest pivot at equation {}",
                    stats_.pivot_ratio, singular_pivot_ratio_, equation),
        equation);
  }
}

void CholmodFactorization::solve(std::span<const double> b, std::span<double> x) {
  if (!factorized_) {
    throw std::logic_error("CHOLMOD: solve before a successful factorize");
  }
  const int n = system_.n();
  if (b.size() != static_cast<std::size_t>(n) || x.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument(fmt::format(
        "CHOLMOD: solve: b and x must have {} entries (got {} and {})", n, b.size(), x.size()));
  }
  Library& lib = *lib_;
  const long long start = detail::clock_ns();
  const std::vector<double>& scale = system_.scale();
  std::vector<double>& rhs = system_.rhs();
  for (int i = 0; i < n; ++i) {
    rhs[i] = scale[i] * b[static_cast<std::size_t>(i)];
  }
  // A dense right-hand side over our own array: CHOLMOD only reads it.
  cholmod_dense rhs_view{};
  rhs_view.nrow = static_cast<std::size_t>(n);
  rhs_view.ncol = 1;
  rhs_view.nzmax = static_cast<std::size_t>(n);
  rhs_view.d = static_cast<std::size_t>(n);
  rhs_view.x = rhs.data();
  rhs_view.z = nullptr;
  rhs_view.xtype = CHOLMOD_REAL;
  rhs_view.dtype = CHOLMOD_DOUBLE;
  if (!cholmod_solve2(CHOLMOD_A, lib.factor, &rhs_view, nullptr, &lib.solution, nullptr,
                      &lib.work_y, &lib.work_e, &lib.common)) {
    lib.check("cholmod_solve2");
    throw std::runtime_error("CHOLMOD: cholmod_solve2 failed");
  }
  const double* y = static_cast<const double*>(lib.solution->x);
  for (int i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = scale[i] * y[i];
  }
  stats_.solve_seconds = detail::seconds_since(start);
}

}  // namespace sf
