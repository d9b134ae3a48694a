#include "implicit/csc_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace sf {

long CscMatrix::nonzeros() const {
  return static_cast<long>(row_index.size());
}

int CscMatrix::find(int row, int col) const {
  if (row < 0 || row >= n || col < 0 || col >= n) {
    return -1;
  }
  const auto first = row_index.begin() + col_start[col];
  const auto last = row_index.begin() + col_start[col + 1];
  const auto it = std::lower_bound(first, last, row);
  if (it == last || *it != row) {
    return -1;
  }
  return static_cast<int>(it - row_index.begin());
}

void CscMatrix::multiply(std::span<const double> x, std::span<double> y) const {
  if (x.size() != static_cast<std::size_t>(n) || y.size() != static_cast<std::size_t>(n)) {
    throw std::invalid_argument("CscMatrix::multiply: x and y must have n = " + std::to_string(n) +
                                " entries (got " + std::to_string(x.size()) + " and " +
                                std::to_string(y.size()) + ")");
  }
  std::fill(y.begin(), y.end(), 0.0);
  for (int j = 0; j < n; ++j) {
    const double xj = x[j];
    for (int p = col_start[j]; p < col_start[j + 1]; ++p) {
      y[row_index[p]] += values[p] * xj;
    }
  }
}

double CscMatrix::asymmetry() const {
  double largest = 0.0;
  double defect = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int p = col_start[j]; p < col_start[j + 1]; ++p) {
      const int i = row_index[p];
      const double aij = values[p];
      largest = std::max(largest, std::abs(aij));
      if (i == j) {
        continue;
      }
      // Each unordered pair is visited from both of its entries; a missing mirror counts as 0.
      const int q = find(j, i);
      const double aji = q < 0 ? 0.0 : values[q];
      defect = std::max(defect, std::abs(aij - aji));
    }
  }
  return largest > 0.0 ? defect / largest : 0.0;
}

void CscMatrix::symmetrize() {
  // Check the whole pattern first, so that a failure leaves the values untouched.
  for (int j = 0; j < n; ++j) {
    for (int p = col_start[j]; p < col_start[j + 1]; ++p) {
      const int i = row_index[p];
      if (i != j && find(j, i) < 0) {
        throw std::invalid_argument("CscMatrix::symmetrize: entry (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ") is stored but (" + std::to_string(j) +
                                    ", " + std::to_string(i) +
                                    ") is not: the pattern is not structurally symmetric");
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int p = col_start[j]; p < col_start[j + 1]; ++p) {
      const int i = row_index[p];
      if (i < j) {
        const int q = find(j, i);
        const double mean = 0.5 * (values[p] + values[q]);
        values[p] = mean;
        values[q] = mean;
      }
    }
  }
}

void CscMatrix::check_structure() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("CscMatrix: " + what); };
  if (n < 0) {
    fail("negative size n = " + std::to_string(n));
  }
  if (col_start.size() != static_cast<std::size_t>(n) + 1) {
    fail("col_start has " + std::to_string(col_start.size()) +
         " entries, n + 1 = " + std::to_string(n + 1) + " expected");
  }
  if (col_start.front() != 0) {
    fail("col_start[0] = " + std::to_string(col_start.front()) + ", 0 expected");
  }
  if (row_index.size() != values.size()) {
    fail("row_index has " + std::to_string(row_index.size()) + " entries but values has " +
         std::to_string(values.size()));
  }
  if (static_cast<std::size_t>(col_start.back()) != row_index.size()) {
    fail("col_start[n] = " + std::to_string(col_start.back()) + " but " +
         std::to_string(row_index.size()) + " entries are stored");
  }
  for (int j = 0; j < n; ++j) {
    const int first = col_start[j];
    const int last = col_start[j + 1];
    if (last < first) {
      fail("col_start decreases at column " + std::to_string(j) + " (" + std::to_string(first) +
           " then " + std::to_string(last) + ")");
    }
    for (int p = first; p < last; ++p) {
      const int i = row_index[p];
      if (i < 0 || i >= n) {
        fail("row index " + std::to_string(i) + " out of range [0, " + std::to_string(n) +
             ") in column " + std::to_string(j));
      }
      if (p > first && i <= row_index[p - 1]) {
        fail("row indices of column " + std::to_string(j) + " not sorted ascending and unique (" +
             std::to_string(row_index[p - 1]) + " then " + std::to_string(i) + ")");
      }
    }
  }
}

Eigen::MatrixXd CscMatrix::to_dense() const {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    for (int p = col_start[j]; p < col_start[j + 1]; ++p) {
      dense(row_index[p], j) += values[p];
    }
  }
  return dense;
}

CscMatrix csc_from_triplets(int n, std::span<const CscTriplet> entries) {
  if (n < 0) {
    throw std::invalid_argument("csc_from_triplets: negative size n = " + std::to_string(n));
  }
  for (const CscTriplet& e : entries) {
    if (e.row < 0 || e.row >= n || e.col < 0 || e.col >= n) {
      throw std::invalid_argument("csc_from_triplets: entry (" + std::to_string(e.row) + ", " +
                                  std::to_string(e.col) + ") outside a " + std::to_string(n) +
                                  " x " + std::to_string(n) + " matrix");
    }
  }
  // Bucket the entries by column, sort each column by row, then merge duplicates.
  std::vector<int> count(static_cast<std::size_t>(n) + 1, 0);
  for (const CscTriplet& e : entries) {
    ++count[e.col + 1];
  }
  for (int j = 0; j < n; ++j) {
    count[j + 1] += count[j];
  }
  std::vector<std::size_t> order(entries.size());
  {
    std::vector<int> next(count.begin(), count.end() - 1);
    for (std::size_t k = 0; k < entries.size(); ++k) {
      order[next[entries[k].col]++] = k;
    }
  }
  CscMatrix a;
  a.n = n;
  a.col_start.assign(static_cast<std::size_t>(n) + 1, 0);
  a.row_index.reserve(entries.size());
  a.values.reserve(entries.size());
  for (int j = 0; j < n; ++j) {
    const auto first = order.begin() + count[j];
    const auto last = order.begin() + count[j + 1];
    std::stable_sort(first, last,
                     [&](std::size_t u, std::size_t v) { return entries[u].row < entries[v].row; });
    for (auto it = first; it != last; ++it) {
      const CscTriplet& e = entries[*it];
      if (static_cast<int>(a.row_index.size()) > a.col_start[j] && a.row_index.back() == e.row) {
        a.values.back() += e.value;
      } else {
        a.row_index.push_back(e.row);
        a.values.push_back(e.value);
      }
    }
    a.col_start[j + 1] = static_cast<int>(a.row_index.size());
  }
  return a;
}

}  // namespace sf
