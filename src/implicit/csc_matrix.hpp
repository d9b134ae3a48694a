#pragma once
// The sparse matrix of the implicit step: a square matrix in compressed-column (CSC) form, the
// layout CHOLMOD and UMFPACK read without conversion.
#include <Eigen/Core>
#include <span>
#include <vector>

namespace sf {

/// A square sparse matrix in compressed-column form, 0-based; row indices sorted ascending and
/// unique within each column.
struct CscMatrix {
  int n = 0;                   ///< rows = columns
  std::vector<int> col_start;  ///< n + 1 entries
  std::vector<int> row_index;  ///< one per stored entry
  std::vector<double> values;  ///< one per stored entry

  /// The number of stored entries (explicit zeros included).
  long nonzeros() const;
  /// Position of entry (row, col) in row_index/values, or -1 when not in the pattern (binary
  /// search). Indices outside [0, n) are not in the pattern.
  int find(int row, int col) const;
  /// y = A x (x, y of size n; no aliasing). Throws std::invalid_argument on a size mismatch.
  /// Allocates nothing.
  void multiply(std::span<const double> x, std::span<double> y) const;
  /// max_ij |a_ij - a_ji| / max_ij |a_ij| over the stored entries (an entry missing from the
  /// pattern counts as 0); 0 for a zero matrix.
  double asymmetry() const;
  /// A <- (A + A^T) / 2 in place. Throws std::invalid_argument when the pattern is not
  /// structurally symmetric.
  void symmetrize();
  /// Throws std::invalid_argument naming the defect when the structure is inconsistent (sizes,
  /// order, range).
  void check_structure() const;
  /// The dense n x n matrix (for tests and small diagnostics).
  Eigen::MatrixXd to_dense() const;
};

/// One entry (row, col, value) of a matrix being assembled.
struct CscTriplet {
  int row = 0;
  int col = 0;
  double value = 0.0;
};

/// The n x n matrix with the given entries, duplicates summed (explicit zeros kept in the
/// pattern). Throws std::invalid_argument for an index outside [0, n).
CscMatrix csc_from_triplets(int n, std::span<const CscTriplet> entries);

}  // namespace sf
