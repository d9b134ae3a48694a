#include "implicit/umfpack_factorization.hpp"

#include <fmt/core.h>
#include <umfpack.h>

#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

namespace sf {

// The UMFPACK objects, owned.
struct UmfpackFactorization::Library {
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  void* symbolic = nullptr;
  void* numeric = nullptr;

  Library() {
    umfpack_di_defaults(control);
    control[UMFPACK_PRL] = 0;  // no report output
    // A is already scaled symmetrically (S A S); a further row scaling would change the pivots
    // the pivot ratio is taken from.
    control[UMFPACK_SCALE] = UMFPACK_SCALE_NONE;
    for (double& v : info) {
      v = 0.0;
    }
  }
  ~Library() {
    free_numeric();
    free_symbolic();
  }
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;

  void free_numeric() {
    if (numeric != nullptr) {
      umfpack_di_free_numeric(&numeric);
    }
  }
  void free_symbolic() {
    if (symbolic != nullptr) {
      umfpack_di_free_symbolic(&symbolic);
    }
  }
};

namespace {

/// Throws for an UMFPACK error (a negative status).
void check_status(int status, const char* call) {
  if (status == UMFPACK_ERROR_out_of_memory) {
    throw std::bad_alloc();
  }
  if (status < 0) {
    throw std::runtime_error(fmt::format("UMFPACK: {} failed with status {}", call, status));
  }
}

}  // namespace

UmfpackFactorization::UmfpackFactorization(double singular_pivot_ratio)
    : lib_(std::make_unique<Library>()), singular_pivot_ratio_(singular_pivot_ratio) {
  stats_.method = FactorizationMethod::umfpack;
}

UmfpackFactorization::~UmfpackFactorization() = default;

void UmfpackFactorization::factorize(const CscMatrix& a) {
  factorized_ = false;
  Library& lib = *lib_;
  const bool new_pattern = system_.update_pattern(a);
  system_.scale_values(a);
  const int n = system_.n();
  stats_.matrix_nonzeros = a.nonzeros();
  if (n == 0) {  // nothing to factorise (UMFPACK refuses an empty matrix)
    stats_.equations = 0;
    stats_.pivot_ratio = 1.0;
    factorized_ = true;
    return;
  }
  const int* ap = system_.col_start().data();
  const int* ai = system_.row_index().data();
  const double* ax = system_.scaled_values().data();
  if (new_pattern || lib.symbolic == nullptr) {
    lib.free_numeric();
    lib.free_symbolic();
    const auto size = static_cast<std::size_t>(n);
    work_int_.assign(size, 0);
    work_double_.assign(5 * size, 0.0);
    solution_.assign(size, 0.0);
    column_order_.assign(size, -1);
    pivots_.assign(size, 0.0);
    const long long start = detail::clock_ns();
    const int status = umfpack_di_symbolic(n, n, ap, ai, ax, &lib.symbolic, lib.control, lib.info);
    stats_.analyse_seconds = detail::seconds_since(start);
    check_status(status, "umfpack_di_symbolic");
    ++stats_.analyses;
    stats_.equations = n;
  }
  lib.free_numeric();
  const long long start = detail::clock_ns();
  const int status =
      umfpack_di_numeric(ap, ai, ax, lib.symbolic, &lib.numeric, lib.control, lib.info);
  stats_.factor_seconds = detail::seconds_since(start);
  ++stats_.factorizations;
  check_status(status, "umfpack_di_numeric");
  // Info's counts include the unit diagonal of L and the diagonal of U: count it once.
  stats_.factor_nonzeros = static_cast<long>(lib.info[UMFPACK_LNZ] + lib.info[UMFPACK_UNZ]) - n;
  stats_.fill_ratio = a.nonzeros() > 0 ? static_cast<double>(stats_.factor_nonzeros) /
                                             static_cast<double>(a.nonzeros())
                                       : 0.0;
  stats_.pivot_ratio = n > 0 ? lib.info[UMFPACK_RCOND] : 1.0;
  if (status == UMFPACK_WARNING_singular_matrix) {
    stats_.pivot_ratio = 0.0;
    const int equation = smallest_pivot_column();
    throw SingularSystemError(
        fmt::format("UMFPACK: the matrix is singular: a zero pivot at equation {}", equation),
        equation);
  }
  if (!(stats_.pivot_ratio >= singular_pivot_ratio_)) {
    const int equation = smallest_pivot_column();
    throw SingularSystemError(
        fmt::format("UMFPACK: the matrix is singular to working precision: pivot ratio {:.3g} "
                    "below {:.3g}, smallest pivot at equation {}",
                    stats_.pivot_ratio, singular_pivot_ratio_, equation),
        equation);
  }
  factorized_ = true;
}

int UmfpackFactorization::smallest_pivot_column() {
  int do_recip = 0;
  const int status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
                                            nullptr, column_order_.data(), pivots_.data(),
                                            &do_recip, nullptr, lib_->numeric);
  if (status != UMFPACK_OK) {
    return -1;
  }
  int smallest = -1;
  double smallest_pivot = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < pivots_.size(); ++k) {
    if (std::abs(pivots_[k]) < smallest_pivot) {
      smallest_pivot = std::abs(pivots_[k]);
      smallest = static_cast<int>(k);
    }
  }
  return smallest >= 0 ? column_order_[static_cast<std::size_t>(smallest)] : -1;
}

void UmfpackFactorization::solve(std::span<const double> b, std::span<double> x) {
  if (!factorized_) {
    throw std::logic_error("UMFPACK: solve before a successful factorize");
  }
  const int n = system_.n();
  if (b.size() != static_cast<std::size_t>(n) || x.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument(fmt::format(
        "UMFPACK: solve: b and x must have {} entries (got {} and {})", n, b.size(), x.size()));
  }
  if (n == 0) {
    return;
  }
  Library& lib = *lib_;
  const long long start = detail::clock_ns();
  const std::vector<double>& scale = system_.scale();
  std::vector<double>& rhs = system_.rhs();
  for (int i = 0; i < n; ++i) {
    rhs[i] = scale[i] * b[static_cast<std::size_t>(i)];
  }
  const int status =
      umfpack_di_wsolve(UMFPACK_A, system_.col_start().data(), system_.row_index().data(),
                        system_.scaled_values().data(), solution_.data(), rhs.data(), lib.numeric,
                        lib.control, lib.info, work_int_.data(), work_double_.data());
  check_status(status, "umfpack_di_wsolve");
  for (int i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = scale[i] * solution_[i];
  }
  stats_.solve_seconds = detail::seconds_since(start);
}

}  // namespace sf
