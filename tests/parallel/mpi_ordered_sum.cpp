// MPI check of the ordered sum (issue 17, item 3: energies and reactions all-reduced exactly):
// each rank sums its share of whole blocks, the block sums are gathered in block order on every
// rank and added in order; the result must equal, bit for bit, the serial ordered_sum on every
// rank, at any rank count. Exit code 0 when it does (run by ctest at 1, 2 and 3 ranks).
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/ordered_sum.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // The same values on every rank (a fixed seed), as a replicated or gathered field would be.
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  std::vector<double> values(7 * sf::kSumBlock + 123);
  for (double& x : values) {
    x = mantissa(random) * std::pow(10.0, exponent(random));
  }
  const std::size_t blocks = sf::ordered_sum_blocks(values.size());
  std::vector<double> all(blocks);
  const double serial = sf::ordered_sum(values, all);

  // This rank's contiguous share of the blocks.
  std::vector<int> counts(static_cast<std::size_t>(size));
  std::vector<int> offsets(static_cast<std::size_t>(size));
  for (int r = 0; r < size; ++r) {
    const std::size_t begin = blocks * static_cast<std::size_t>(r) / static_cast<std::size_t>(size);
    const std::size_t end =
        blocks * static_cast<std::size_t>(r + 1) / static_cast<std::size_t>(size);
    offsets[static_cast<std::size_t>(r)] = static_cast<int>(begin);
    counts[static_cast<std::size_t>(r)] = static_cast<int>(end - begin);
  }
  const auto mine = static_cast<std::size_t>(rank);
  std::vector<double> local(static_cast<std::size_t>(counts[mine]));
  sf::sum_blocks(values, static_cast<std::size_t>(offsets[mine]), local.size(), local);
  std::vector<double> gathered(blocks);
  MPI_Allgatherv(local.data(), counts[mine], MPI_DOUBLE, gathered.data(), counts.data(),
                 offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  const double distributed = sf::add_in_order(gathered);

  const int ok_here = distributed == serial ? 1 : 0;
  int ok_everywhere = 0;
  MPI_Allreduce(&ok_here, &ok_everywhere, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%d ranks: ordered sum %.17g, serial %.17g: %s\n", size, distributed, serial,
                ok_everywhere ? "the same bits" : "DIFFERENT");
  }
  MPI_Finalize();
  return ok_everywhere ? 0 : 1;
}
