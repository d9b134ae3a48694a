// CscMatrix (src/implicit/csc_matrix.hpp): lookup, product, symmetry measures and structure
// checks against hand-worked matrices and dense Eigen.
#include <gtest/gtest.h>

#include <random>
#include <span>
#include <string>
#include <vector>

#include "implicit/csc_matrix.hpp"

namespace sf {
namespace {

// The 4 x 4 matrix
//   [ 4  1  0  0 ]
//   [ 2  5  0  7 ]
//   [ 0  3  6  0 ]
//   [ 0  0  0  8 ]
// (column 3 holds (1, 3) = 7 without a (3, 1) mirror; (2, 1) = 3 without a (1, 2) mirror.)
CscMatrix known_matrix() {
  CscMatrix a;
  a.n = 4;
  a.col_start = {0, 2, 4, 5, 7};
  a.row_index = {0, 1, 0, 2, 2, 1, 3};
  a.values = {4, 2, 1, 3, 6, 7, 8};
  a.check_structure();
  return a;
}

/// The 0 x 0 matrix.
CscMatrix empty_matrix() {
  CscMatrix a;
  a.col_start = {0};
  return a;
}

template <class F>
std::string invalid_argument_message(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

TEST(CscMatrix, FindsStoredEntriesOnly) {
  const CscMatrix a = known_matrix();
  EXPECT_EQ(a.nonzeros(), 7);
  EXPECT_EQ(a.find(0, 0), 0);
  EXPECT_EQ(a.find(1, 0), 1);
  EXPECT_EQ(a.find(0, 1), 2);
  EXPECT_EQ(a.find(2, 1), 3);
  EXPECT_EQ(a.find(2, 2), 4);
  EXPECT_EQ(a.find(1, 3), 5);
  EXPECT_EQ(a.find(3, 3), 6);
  EXPECT_EQ(a.find(1, 1), -1);  // a zero of the pattern
  EXPECT_EQ(a.find(3, 1), -1);
  EXPECT_EQ(a.find(0, 3), -1);
  EXPECT_EQ(a.find(-1, 0), -1);  // outside the matrix
  EXPECT_EQ(a.find(0, 4), -1);
  EXPECT_EQ(a.find(4, 4), -1);
}

TEST(CscMatrix, MultiplyMatchesDenseProduct) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::bernoulli_distribution keep(0.15);
  const int n = 40;
  std::vector<CscTriplet> entries;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (keep(rng)) {
        entries.push_back({i, j, value(rng)});
      }
    }
  }
  const CscMatrix a = csc_from_triplets(n, entries);
  a.check_structure();
  EXPECT_EQ(a.nonzeros(), static_cast<long>(entries.size()));
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (const CscTriplet& e : entries) {
    dense(e.row, e.col) = e.value;
  }
  EXPECT_EQ(a.to_dense(), dense);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) {
    x[i] = value(rng);
  }
  Eigen::VectorXd y = Eigen::VectorXd::Constant(n, 99.0);  // overwritten, not accumulated
  a.multiply(std::span<const double>(x.data(), n), std::span<double>(y.data(), n));
  const Eigen::VectorXd expected = dense * x;
  EXPECT_LT((y - expected).norm(), 1e-14 * expected.norm());

  std::vector<double> short_y(n - 1);
  EXPECT_THROW(a.multiply(std::span<const double>(x.data(), n), short_y), std::invalid_argument);
}

TEST(CscMatrix, FromTripletsSumsDuplicates) {
  const std::vector<CscTriplet> entries = {{1, 0, 2.0}, {0, 0, 1.0}, {1, 0, 0.5}, {2, 2, 0.0}};
  const CscMatrix a = csc_from_triplets(3, entries);
  a.check_structure();
  EXPECT_EQ(a.col_start, (std::vector<int>{0, 2, 2, 3}));
  EXPECT_EQ(a.row_index, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(a.values, (std::vector<double>{1.0, 2.5, 0.0}));  // the explicit zero stays
  EXPECT_THROW(csc_from_triplets(3, std::vector<CscTriplet>{{3, 0, 1.0}}), std::invalid_argument);
}

TEST(CscMatrix, AsymmetryOfKnownMatrices) {
  // Pairs: (0,1)/(1,0): |1 - 2| = 1; (1,2) missing vs (2,1) = 3: 3; (1,3) = 7 vs missing: 7.
  // Largest entry 8: 7 / 8.
  EXPECT_DOUBLE_EQ(known_matrix().asymmetry(), 7.0 / 8.0);
  CscMatrix b = known_matrix();
  b.values[5] = 0.0;  // (1,3): now the largest defect is 3
  EXPECT_DOUBLE_EQ(b.asymmetry(), 3.0 / 8.0);
  const CscMatrix symmetric =
      csc_from_triplets(2, std::vector<CscTriplet>{{0, 0, 2}, {1, 0, -1}, {0, 1, -1}, {1, 1, 2}});
  EXPECT_EQ(symmetric.asymmetry(), 0.0);
  const CscMatrix zero = csc_from_triplets(2, std::vector<CscTriplet>{{1, 0, 0.0}});
  EXPECT_EQ(zero.asymmetry(), 0.0);
  EXPECT_EQ(empty_matrix().asymmetry(), 0.0);
}

TEST(CscMatrix, SymmetrizeAveragesMirrorEntries) {
  CscMatrix a = csc_from_triplets(
      3, std::vector<CscTriplet>{
             {0, 0, 4}, {1, 0, 2}, {0, 1, 1}, {1, 1, 5}, {2, 1, -3}, {1, 2, 3}, {2, 2, 6}});
  a.symmetrize();
  Eigen::Matrix3d expected;
  expected << 4, 1.5, 0, 1.5, 5, 0, 0, 0, 6;
  EXPECT_EQ(a.to_dense(), Eigen::MatrixXd(expected));
  EXPECT_EQ(a.asymmetry(), 0.0);

  CscMatrix b = known_matrix();  // (2,1) has no mirror
  const std::vector<double> before = b.values;
  const std::string message = invalid_argument_message([&] { b.symmetrize(); });
  EXPECT_NE(message.find("not structurally symmetric"), std::string::npos) << message;
  EXPECT_EQ(b.values, before);  // untouched
}

TEST(CscMatrix, CheckStructureNamesEachDefect) {
  EXPECT_NO_THROW(known_matrix().check_structure());
  EXPECT_NO_THROW(empty_matrix().check_structure());
  struct Case {
    const char* expected;  ///< a phrase of the message
    void (*spoil)(CscMatrix&);
  };
  const Case cases[] = {
      {"negative size", [](CscMatrix& a) { a.n = -1; }},
      {"col_start has 4 entries", [](CscMatrix& a) { a.col_start.pop_back(); }},
      {"col_start[0] = 1", [](CscMatrix& a) { a.col_start[0] = 1; }},
      {"values has 6", [](CscMatrix& a) { a.values.pop_back(); }},
      {"col_start[n] = 6 but 7 entries", [](CscMatrix& a) { a.col_start[4] = 6; }},
      {"col_start decreases at column 1", [](CscMatrix& a) { a.col_start[2] = 1; }},
      {"row index 4 out of range", [](CscMatrix& a) { a.row_index[6] = 4; }},
      {"row index -1 out of range", [](CscMatrix& a) { a.row_index[0] = -1; }},
      {"column 1 not sorted", [](CscMatrix& a) { std::swap(a.row_index[2], a.row_index[3]); }},
      {"column 0 not sorted ascending and unique", [](CscMatrix& a) { a.row_index[1] = 0; }},
  };
  for (const Case& c : cases) {
    CscMatrix a = known_matrix();
    c.spoil(a);
    const std::string message = invalid_argument_message([&] { a.check_structure(); });
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "expected \"" << c.expected << "\" in: " << message;
  }
}

}  // namespace
}  // namespace sf
