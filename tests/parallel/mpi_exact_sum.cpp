// MPI check of the exact sum (issue 17, item 3: energies and reactions all-reduced exactly):
// each rank adds an interleaved share of the same values (every size-th one, as a partition
// scatters a mesh's numbering), allreduce_exact adds the ranks' sums, and the result must equal,
// bit for bit, the serial exact sum on every rank, at any rank count. Exit code 0 when it does
// (run by ctest at 1, 2 and 3 ranks).
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/exact_sum.hpp"
#include "parallel/exact_allreduce.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // The same values on every rank (a fixed seed): mixed signs over 12 decades.
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-6, 6);
  std::vector<double> values(20000);
  for (double& x : values) {
    x = mantissa(random) * std::pow(10.0, exponent(random));
  }
  sf::ExactSum serial[2];
  sf::ExactSum mine[2];
  for (std::size_t i = 0; i < values.size(); ++i) {
    serial[0].add(values[i]);
    serial[1].add(values[i] * values[i]);
    if (static_cast<int>(i % static_cast<std::size_t>(size)) == rank) {
      mine[0].add(values[i]);
      mine[1].add(values[i] * values[i]);
    }
  }
  sf::allreduce_exact(mine, MPI_COMM_WORLD);
  double plain = 0.0;  // the naive sum, for the printout: its last bits depend on the order
  for (const double x : values) {
    plain += x;
  }
  const int ok_here = mine[0].round() == serial[0].round() && mine[1].round() == serial[1].round();
  int ok_everywhere = 0;
  MPI_Allreduce(&ok_here, &ok_everywhere, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf("%d ranks: exact sum %.17g (serial %.17g, left to right %.17g): %s\n", size,
                mine[0].round(), serial[0].round(), plain,
                ok_everywhere ? "the same bits" : "DIFFERENT");
  }
  MPI_Finalize();
  return ok_everywhere ? 0 : 1;
}
