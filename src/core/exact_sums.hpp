#pragma once
// K sums over an index range, exact (core/exact_sum.hpp), with OpenMP threads sharing out the
// indices: the sums do not depend on the thread count. For the node sums of a step (energies,
// works), where each index contributes K terms.
#include <array>

#include "core/exact_sum.hpp"

namespace sf {

/// Below this many indices the sums run on one thread (a parallel region costs microseconds).
inline constexpr long kMinParallelIndices = 1024;

/// The K exact sums over i in [0, n) of the terms that terms(i, t) writes to t[0..K). terms is
/// called once per index, from any thread (it may update index i's own data).
template <int K, class Terms>
std::array<ExactSum, K> sum_exactly(long n, const Terms& terms) {
  std::array<ExactSum, K> total;
#pragma omp parallel if (n >= kMinParallelIndices)
  {
    std::array<ExactSum, K> mine;
    double t[K];
#pragma omp for schedule(static) nowait
    for (long i = 0; i < n; ++i) {
      terms(i, t);
      for (int k = 0; k < K; ++k) {
        mine[k].add(t[k]);
      }
    }
    // Exact merges commute: the order in which the threads arrive cannot change a bit.
#pragma omp critical(sf_sum_exactly)
    for (int k = 0; k < K; ++k) {
      total[k].merge(mine[k]);
    }
  }
  return total;
}

/// Each sum rounded once to the nearest double.
template <std::size_t K>
std::array<double, K> rounded(const std::array<ExactSum, K>& sums) {
  std::array<double, K> values;
  for (std::size_t k = 0; k < K; ++k) {
    values[k] = sums[k].round();
  }
  return values;
}

}  // namespace sf
