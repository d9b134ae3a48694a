#include "implicit/sparse_factorization.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "implicit/cholmod_factorization.hpp"
#include "implicit/umfpack_factorization.hpp"

namespace sf {

const char* method_name(FactorizationMethod m) {
  switch (m) {
    case FactorizationMethod::cholmod:
      return "CHOLMOD";
    case FactorizationMethod::umfpack:
      return "UMFPACK";
  }
  return "unknown";
}

SingularSystemError::SingularSystemError(const std::string& what, int equation)
    : std::runtime_error(what), equation_(equation) {}

std::unique_ptr<SparseFactorization> make_factorization(FactorizationMethod method,
                                                        double singular_pivot_ratio) {
  if (!std::isfinite(singular_pivot_ratio) || singular_pivot_ratio < 0.0) {
    throw std::invalid_argument(
        "make_factorization: singular_pivot_ratio must be finite and >= 0 (got " +
        std::to_string(singular_pivot_ratio) + ")");
  }
  switch (method) {
    case FactorizationMethod::cholmod:
      return std::make_unique<CholmodFactorization>(singular_pivot_ratio);
    case FactorizationMethod::umfpack:
      return std::make_unique<UmfpackFactorization>(singular_pivot_ratio);
  }
  throw std::invalid_argument("make_factorization: unknown method");
}

namespace detail {

bool ScaledSystem::update_pattern(const CscMatrix& a) {
  a.check_structure();
  for (std::size_t p = 0; p < a.values.size(); ++p) {
    if (!std::isfinite(a.values[p])) {
      int col = 0;
      while (a.col_start[static_cast<std::size_t>(col) + 1] <= static_cast<int>(p)) {
        ++col;
      }
      throw std::invalid_argument("sparse factorisation: entry (" + std::to_string(a.row_index[p]) +
                                  ", " + std::to_string(col) + ") of A is not finite");
    }
  }
  if (a.n == n_ && a.col_start == col_start_ && a.row_index == row_index_) {
    return false;
  }
  n_ = a.n;
  col_start_ = a.col_start;
  row_index_ = a.row_index;
  diagonal_.assign(static_cast<std::size_t>(n_), -1);
  upper_nonzeros_ = 0;
  for (int j = 0; j < n_; ++j) {
    for (int p = col_start_[j]; p < col_start_[j + 1]; ++p) {
      const int i = row_index_[p];
      if (i <= j) {
        ++upper_nonzeros_;
      }
      if (i == j) {
        diagonal_[j] = p;
      }
    }
  }
  scale_.assign(static_cast<std::size_t>(n_), 1.0);
  scaled_.assign(row_index_.size(), 0.0);
  rhs_.assign(static_cast<std::size_t>(n_), 0.0);
  return true;
}

void ScaledSystem::scale_values(const CscMatrix& a) {
  for (int j = 0; j < n_; ++j) {
    const double d = diagonal_[j] < 0 ? 0.0 : std::abs(a.values[diagonal_[j]]);
    scale_[j] = d > 0.0 ? 1.0 / std::sqrt(d) : 1.0;
  }
  for (int j = 0; j < n_; ++j) {
    for (int p = col_start_[j]; p < col_start_[j + 1]; ++p) {
      scaled_[p] = scale_[row_index_[p]] * a.values[p] * scale_[j];
    }
  }
}

long long clock_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

double seconds_since(long long start_ns) {
  return 1e-9 * static_cast<double>(clock_ns() - start_ns);
}

}  // namespace detail

}  // namespace sf
