// ordered_sum: the same bits at 1, 2 and 3 threads, equal to the block-by-block serial formula,
// and within the rounding bound of the exact sum.
#include "core/ordered_sum.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <vector>

namespace sf {
namespace {

// Values of mixed signs over 12 decades, where the order of the additions shows in the bits.
std::vector<double> awkward_values(std::size_t n) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  std::vector<double> v(n);
  for (double& x : v) {
    x = mantissa(random) * std::pow(10.0, exponent(random));
  }
  return v;
}

TEST(OrderedSum, SameBitsAtAnyThreadCount) {
  const std::vector<double> v = awkward_values(10 * kSumBlock + 377);  // a partial last block
  std::vector<double> scratch(ordered_sum_blocks(v.size()));
  const int threads_before = omp_get_max_threads();
  std::vector<double> sums;
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    sums.push_back(ordered_sum(v, scratch));
  }
  omp_set_num_threads(threads_before);
  EXPECT_EQ(sums[0], sums[1]);
  EXPECT_EQ(sums[0], sums[2]);
  // The naive sum in index order differs in the last bits on these values (the test would not
  // see an order change otherwise).
  double naive = 0.0;
  for (const double x : v) {
    naive += x;
  }
  EXPECT_NE(naive, sums[0]);
}

TEST(OrderedSum, IsTheBlockByBlockSerialSumAndCloseToTheExactOne) {
  const std::vector<double> v = awkward_values(5 * kSumBlock + 1);
  std::vector<double> scratch(ordered_sum_blocks(v.size()));
  double expected = 0.0;
  long double exact = 0.0L;
  double magnitude = 0.0;
  for (std::size_t b = 0; b * kSumBlock < v.size(); ++b) {
    double block = 0.0;
    for (std::size_t i = b * kSumBlock; i < std::min(v.size(), (b + 1) * kSumBlock); ++i) {
      block += v[i];
      exact += v[i];
      magnitude += std::abs(v[i]);
    }
    expected += block;
  }
  EXPECT_EQ(ordered_sum(v, scratch), expected);
  // Recursive summation's bound (Higham 2002, eq. 4.4): |error| <= (n - 1) u sum |x_i|.
  const double bound = static_cast<double>(v.size()) * 1.11e-16 * magnitude;
  EXPECT_LE(std::abs(static_cast<long double>(expected) - exact), bound);
}

TEST(OrderedSum, EmptyAndShortScratch) {
  std::vector<double> scratch;
  EXPECT_EQ(ordered_sum({}, scratch), 0.0);
  const std::vector<double> v(kSumBlock + 1, 1.0);
  std::vector<double> one(1);
  EXPECT_THROW(ordered_sum(v, one), std::invalid_argument);
}

}  // namespace
}  // namespace sf
