#include "core/exact_sum.hpp"

#include <cmath>
#include <limits>

namespace sf {

void ExactSum::propagate_carries() {
  constexpr std::int64_t kBase = std::int64_t{1} << 32;
  for (int k = 0; k + 1 < kDigits; ++k) {
    const std::int64_t carry = digits_[k] >> 32;  // floor(digit / 2^32), also for negatives
    digits_[k] -= carry * kBase;
    digits_[k + 1] += carry;
  }
  pending_ = 0;
}

void ExactSum::merge(const ExactSum& other) {
  ExactSum canonical = other;
  canonical.propagate_carries();
  propagate_carries();
  for (int k = 0; k < kDigits; ++k) {
    digits_[k] += canonical.digits_[k];
  }
  for (int k = 0; k < 3; ++k) {
    specials_[k] += canonical.specials_[k];
  }
  pending_ = 2;  // every digit now holds at most two canonical digits' worth
}

void ExactSum::add_special(std::uint64_t bits) {
  const bool nan = (bits & ((std::uint64_t{1} << 52) - 1)) != 0;
  specials_[nan ? 2 : (bits >> 63 ? 1 : 0)] += 1;
}

double ExactSum::round() const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (specials_[2] > 0 || (specials_[0] > 0 && specials_[1] > 0)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (specials_[0] > 0 || specials_[1] > 0) {
    return specials_[0] > 0 ? kInf : -kInf;
  }
  ExactSum c = *this;
  c.propagate_carries();
  const bool negative = c.digits_[kDigits - 1] < 0;
  if (negative) {
    for (std::int64_t& d : c.digits_) {
      d = -d;
    }
    c.propagate_carries();
  }
  int top = kDigits - 1;
  while (top >= 0 && c.digits_[top] == 0) {
    --top;
  }
  if (top < 0) {
    return 0.0;
  }
  // The top three digits (65 to 96 significant bits) and a sticky bit for all below: enough for
  // one correct rounding of the 128-bit integer to 53 bits.
  const int low = top >= 2 ? top - 2 : 0;
  Uint128 n = 0;
  for (int k = top; k >= low; --k) {
    n = (n << 32) | static_cast<std::uint32_t>(c.digits_[k]);
  }
  bool sticky = false;
  for (int k = 0; k < low; ++k) {
    sticky = sticky || c.digits_[k] != 0;
  }
  if (sticky) {
    n |= 1;
  }
  const double magnitude = std::ldexp(static_cast<double>(n), 32 * low - 1074);
  return negative ? -magnitude : magnitude;
}

}  // namespace sf
