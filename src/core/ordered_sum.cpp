#include "core/ordered_sum.hpp"

#include <algorithm>
#include <stdexcept>

namespace sf {

void sum_blocks(std::span<const double> values, std::size_t first_block, std::size_t count,
                std::span<double> block_sums) {
  if (block_sums.size() < count) {
    throw std::invalid_argument("sum_blocks: block_sums holds fewer than `count` values");
  }
  const auto blocks = static_cast<long>(count);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < blocks; ++k) {
    const std::size_t begin = (first_block + static_cast<std::size_t>(k)) * kSumBlock;
    const std::size_t end = std::min(begin + kSumBlock, values.size());
    double s = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
      s += values[i];
    }
    block_sums[static_cast<std::size_t>(k)] = s;
  }
}

double add_in_order(std::span<const double> block_sums) {
  double s = 0.0;
  for (const double b : block_sums) {
    s += b;
  }
  return s;
}

double ordered_sum(std::span<const double> values, std::span<double> block_scratch) {
  const std::size_t blocks = ordered_sum_blocks(values.size());
  if (block_scratch.size() < blocks) {
    throw std::invalid_argument("ordered_sum: block_scratch holds fewer than the blocks");
  }
  sum_blocks(values, 0, blocks, block_scratch);
  return add_in_order(block_scratch.first(blocks));
}

}  // namespace sf
