#pragma once
// An exact sum of doubles: the value of a sum that cannot depend on the order of its terms, so on
// how the work was split over threads or MPI ranks (issue 17: global scalars reduced exactly).
//
// Every finite double is an integer multiple of 2^-1074. The accumulator holds that integer as
// 66 signed 64-bit digits of 32 bits each (digit k weighs 2^(32 k - 1074)); adding a double adds
// its 53-bit significand, shifted into place, to three neighbouring digits. Integer additions are
// exact and commute, so any order, any split and any merge give the same digits, and round() the
// same double: the exact sum rounded once, to nearest. Infinities and NaN are counted apart and
// give inf, -inf or NaN as IEEE addition would (inf + -inf = NaN).
// Cost: about as much as a few floating-point additions per term; no allocation.
#include <array>
#include <cstdint>

namespace sf {

__extension__ typedef unsigned __int128 Uint128;  // GCC and Clang; -Wpedantic quiet

class ExactSum {
 public:
  /// Digits of 32 bits: 2046 shifts of a 53-bit significand, two more digits for its top bits.
  static constexpr int kDigits = 66;

  void add(double value) {
    std::uint64_t bits;
    __builtin_memcpy(&bits, &value, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased == 0x7ff) {
      add_special(bits);
      return;
    }
    // value = significand 2^(shift - 1074): normal numbers have the implicit bit and shift
    // biased - 1, subnormals (biased 0) neither.
    const std::uint64_t normal = biased != 0 ? 1 : 0;
    const std::uint64_t significand = (bits & ((std::uint64_t{1} << 52) - 1)) | (normal << 52);
    const int shift = biased - static_cast<int>(normal);
    const Uint128 placed = static_cast<Uint128>(significand) << (shift & 31);
    const int k = shift >> 5;
    // Negative values subtract: x -> (x ^ m) - m negates when m = -1 (no branch on the sign,
    // which mixed-sign terms would mispredict).
    const std::int64_t m = -static_cast<std::int64_t>(bits >> 63);
    const auto lo = static_cast<std::int64_t>(static_cast<std::uint32_t>(placed));
    const auto mid = static_cast<std::int64_t>(static_cast<std::uint32_t>(placed >> 32));
    const auto hi = static_cast<std::int64_t>(static_cast<std::uint64_t>(placed >> 64));
    digits_[k] += (lo ^ m) - m;
    digits_[k + 1] += (mid ^ m) - m;
    digits_[k + 2] += (hi ^ m) - m;
    if (++pending_ == kCarryInterval) {
      propagate_carries();
    }
  }

  /// Adds another accumulator's terms (exact: the merged sum is that of all terms).
  void merge(const ExactSum& other);

  /// The exact sum rounded to the nearest double (ties to even); +-inf beyond the double range.
  double round() const;

  void clear() { *this = ExactSum(); }

  /// Moves the carries up so that every digit but the top one is in [0, 2^32): the canonical
  /// form, in which equal sums have equal digits (what an MPI reduction of the digits needs).
  void propagate_carries();

  /// The digits (canonical after propagate_carries), for a reduction over MPI ranks.
  std::array<std::int64_t, kDigits>& digits() { return digits_; }
  const std::array<std::int64_t, kDigits>& digits() const { return digits_; }
  /// The counts of +inf, -inf and NaN terms (a reduction adds them too).
  std::array<std::int64_t, 3>& specials() { return specials_; }

 private:
  // A digit takes 2^31 additions of a 32-bit part before it could overflow; carry well before.
  static constexpr int kCarryInterval = 1 << 30;

  void add_special(std::uint64_t bits);

  std::array<std::int64_t, kDigits> digits_{};
  std::array<std::int64_t, 3> specials_{};  // +inf, -inf, NaN
  int pending_ = 0;                         // additions since the carries were last moved up
};

}  // namespace sf
