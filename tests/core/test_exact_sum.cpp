// ExactSum against math.fsum (Python's correctly rounded sum; the values below are printed by
// it for the same generator), and the same bits for any order, split and thread count.
#include "core/exact_sum.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace sf {
namespace {

// Signed 53-bit significands from a 64-bit LCG, exponents cycling over `spread` binades: the
// same doubles as the Python generator that computed the references with math.fsum.
std::vector<double> awkward_values(int n, int spread) {
  std::uint64_t x = 12345;
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto m = static_cast<std::int64_t>(x >> 11) - (std::int64_t{1} << 52);
    const int e = (i * 7) % spread - spread / 2 - 52;
    v[static_cast<std::size_t>(i)] = std::ldexp(static_cast<double>(m), e);
  }
  return v;
}

double exact_sum(const std::vector<double>& v) {
  ExactSum s;
  for (const double x : v) {
    s.add(x);
  }
  return s.round();
}

TEST(ExactSum, EqualsTheCorrectlyRoundedSum) {
  // References: math.fsum of the same values (Python 3.11); the plain left-to-right sum differs.
  EXPECT_EQ(exact_sum(awkward_values(10000, 40)), 0x1.bd9405a639218p+22);
  EXPECT_EQ(exact_sum(awkward_values(100000, 200)), -0x1.b640a60500237p+102);
  EXPECT_EQ(exact_sum(awkward_values(1000, 2000)), 0x1.6e33905f38f18p+997);
  EXPECT_EQ(exact_sum({0.1, 0.2, 0.3}), 0x1.3333333333333p-1);  // left to right: ...334p-1
  EXPECT_EQ(exact_sum({1e100, 1.0, -1e100}), 1.0);
  EXPECT_EQ(exact_sum({1.0, -1.0}), 0.0);
  EXPECT_EQ(exact_sum({}), 0.0);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(exact_sum({tiny, tiny, tiny}), 3.0 * tiny);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(exact_sum({big, big, -big}), big);  // no overflow in between
  EXPECT_EQ(exact_sum({big, big}), std::numeric_limits<double>::infinity());
}

TEST(ExactSum, InfinitiesAndNanAsIeeeAddition) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(exact_sum({1.0, inf, 2.0}), inf);
  EXPECT_EQ(exact_sum({-inf, 1.0}), -inf);
  EXPECT_TRUE(std::isnan(exact_sum({inf, -inf})));
  EXPECT_TRUE(std::isnan(exact_sum({1.0, std::numeric_limits<double>::quiet_NaN()})));
}

TEST(ExactSum, SameBitsForAnyOrderAndSplit) {
  std::vector<double> v = awkward_values(20000, 120);
  const double reference = exact_sum(v);
  std::mt19937 random(3);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(v.begin(), v.end(), random);
    // Three accumulators over uneven shares, merged in some order.
    ExactSum parts[3];
    for (std::size_t i = 0; i < v.size(); ++i) {
      parts[(i * 7 + static_cast<std::size_t>(trial)) % 3].add(v[i]);
    }
    parts[trial % 3].merge(parts[(trial + 1) % 3]);
    parts[trial % 3].merge(parts[(trial + 2) % 3]);
    EXPECT_EQ(parts[trial % 3].round(), reference) << "trial " << trial;
  }
}

TEST(ExactSum, CanonicalDigitsDoNotDependOnTheOrder) {
  // What an MPI reduction of the digits relies on: equal sums, equal canonical digits.
  std::vector<double> v = awkward_values(5000, 80);
  ExactSum forward;
  ExactSum backward;
  for (std::size_t i = 0; i < v.size(); ++i) {
    forward.add(v[i]);
    backward.add(v[v.size() - 1 - i]);
  }
  forward.propagate_carries();
  backward.propagate_carries();
  EXPECT_EQ(forward.digits(), backward.digits());
}

TEST(ExactSum, SameBitsAtOneTwoAndThreeThreads) {
  const std::vector<double> v = awkward_values(50000, 300);
  const int threads_before = omp_get_max_threads();
  std::vector<double> results;
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    std::vector<ExactSum> per_thread(static_cast<std::size_t>(threads));
#pragma omp parallel
    {
      ExactSum& mine = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < v.size(); ++i) {
        mine.add(v[i]);
      }
    }
    for (std::size_t t = 1; t < per_thread.size(); ++t) {
      per_thread[0].merge(per_thread[t]);
    }
    results.push_back(per_thread[0].round());
  }
  omp_set_num_threads(threads_before);
  EXPECT_EQ(results[0], exact_sum(v));
  EXPECT_EQ(results[1], results[0]);
  EXPECT_EQ(results[2], results[0]);
}

}  // namespace
}  // namespace sf
