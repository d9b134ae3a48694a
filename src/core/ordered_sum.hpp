#pragma once
// A sum whose bits do not depend on how the work is split: over threads (OpenMP) or over MPI
// ranks. The values are summed in fixed blocks of kSumBlock in index order, then the block sums
// in block order; threads and ranks only share out whole blocks (issue 17: global scalars reduced
// in a fixed order).
#include <cstddef>
#include <span>

namespace sf {

/// Values per block of an ordered sum: the unit of work a thread or a rank takes.
inline constexpr std::size_t kSumBlock = 1024;

/// The number of blocks (the scratch size ordered_sum needs) for n values.
constexpr std::size_t ordered_sum_blocks(std::size_t n) {
  return (n + kSumBlock - 1) / kSumBlock;
}

/// The sum of values[first_block * kSumBlock, ...) block by block into block_sums[0..count):
/// block b's values summed in index order (0.0 + v0 + v1 + ...). Threads (OpenMP, when the
/// caller is not in a parallel region) share out the blocks; each block is one thread's.
void sum_blocks(std::span<const double> values, std::size_t first_block, std::size_t count,
                std::span<double> block_sums);

/// The block sums added in block order (0.0 + s0 + s1 + ...): serial, a few values.
double add_in_order(std::span<const double> block_sums);

/// The ordered sum of `values`: sum_blocks over all of them, then add_in_order. The same bits for
/// any thread count, and the same as the block sums of several ranks gathered in block order.
/// block_scratch holds at least ordered_sum_blocks(values.size()) values (no allocation here).
double ordered_sum(std::span<const double> values, std::span<double> block_scratch);

}  // namespace sf
