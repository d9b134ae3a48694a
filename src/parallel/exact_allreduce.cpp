#include "parallel/exact_allreduce.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace sf {

void allreduce_exact(std::span<ExactSum> sums, MPI_Comm comm) {
  constexpr int kWidth = ExactSum::kDigits + 3;  // the digits, then the +inf, -inf, NaN counts
  if (sums.size() > static_cast<std::size_t>(kMaxExactAllreduce)) {
    throw std::invalid_argument("allreduce_exact: more than kMaxExactAllreduce sums");
  }
  std::int64_t buffer[kMaxExactAllreduce * kWidth];
  const int count = static_cast<int>(sums.size()) * kWidth;
  for (std::size_t s = 0; s < sums.size(); ++s) {
    sums[s].propagate_carries();  // digits in [0, 2^32): no overflow for up to 2^31 ranks
    std::int64_t* row = buffer + s * kWidth;
    for (int k = 0; k < ExactSum::kDigits; ++k) {
      row[k] = sums[s].digits()[static_cast<std::size_t>(k)];
    }
    for (int k = 0; k < 3; ++k) {
      row[ExactSum::kDigits + k] = sums[s].specials()[static_cast<std::size_t>(k)];
    }
  }
  const int status = MPI_Allreduce(MPI_IN_PLACE, buffer, count, MPI_INT64_T, MPI_SUM, comm);
  if (status != MPI_SUCCESS) {
    throw std::runtime_error("allreduce_exact: MPI_Allreduce failed (code " +
                             std::to_string(status) + ")");
  }
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const std::int64_t* row = buffer + s * kWidth;
    for (int k = 0; k < ExactSum::kDigits; ++k) {
      sums[s].digits()[static_cast<std::size_t>(k)] = row[k];
    }
    for (int k = 0; k < 3; ++k) {
      sums[s].specials()[static_cast<std::size_t>(k)] = row[ExactSum::kDigits + k];
    }
    sums[s].propagate_carries();
  }
}

}  // namespace sf
