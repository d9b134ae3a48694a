#pragma once
// The exact sums of all ranks (core/exact_sum.hpp), added on every rank: each rank's digits are
// made canonical, then summed by MPI_Allreduce on 64-bit integers, which is exact whatever order
// the MPI library adds them in. So a global energy or tool reaction has the same bits on every
// rank and at any rank count (issue 17).
#include <mpi.h>

#include <span>

#include "core/exact_sum.hpp"

namespace sf {

/// Replaces each of `sums` by the sum over all ranks of `comm` (collective: every rank calls it
/// with the same number of sums). At most kMaxExactAllreduce sums per call; no allocation.
void allreduce_exact(std::span<ExactSum> sums, MPI_Comm comm);

inline constexpr int kMaxExactAllreduce = 64;

}  // namespace sf
