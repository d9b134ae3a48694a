#pragma once
// A block of 4 doubles processed as one value (GCC/Clang vector extension): generic x86-64 runs
// each operation as two SSE2 instructions, a function compiled for x86-64-v3 as one AVX2
// instruction. Every operation is the correctly rounded IEEE operation lane by lane, so a kernel
// written once for `double` and for `Block` gives the same bits in each lane as the scalar code
// (the build has -ffp-contract=off: no fused multiply-add). Comparisons give a `BlockMask` (all
// bits set: true); `mask ? a : b` selects lane by lane.
#include <cmath>
#include <cstring>
#include <limits>

namespace sf {

inline constexpr int kBlockLanes = 4;
using Block = double __attribute__((vector_size(kBlockLanes * sizeof(double))));
using BlockMask = long __attribute__((vector_size(kBlockLanes * sizeof(double))));  // as compared

// The helpers are forced inline, so that a multiversioned caller carries its own copy built for
// its instruction set.
#define SF_BLOCK_INLINE [[gnu::always_inline]] inline

SF_BLOCK_INLINE Block load_block(const double* p) {
  Block v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
SF_BLOCK_INLINE void store_block(double* p, const Block& v) {
  std::memcpy(p, &v, sizeof v);
}
SF_BLOCK_INLINE Block broadcast(double x) {
  return Block{} + x;
}
/// |v| for comparisons (-0.0 stays -0.0, which compares equal to 0.0).
SF_BLOCK_INLINE Block block_abs(const Block& v) {
  return v < 0.0 ? -v : v;
}
SF_BLOCK_INLINE Block block_sqrt(const Block& v) {
  Block r;
  for (int j = 0; j < kBlockLanes; ++j) {
    r[j] = std::sqrt(v[j]);
  }
  return r;
}
/// Lane by lane what std::min(a, b) gives: (b < a) ? b : a.
SF_BLOCK_INLINE Block block_min(const Block& a, const Block& b) {
  return b < a ? b : a;
}
/// Lane by lane std::isfinite.
SF_BLOCK_INLINE BlockMask block_isfinite(const Block& v) {
  return block_abs(v) < std::numeric_limits<double>::infinity();
}

}  // namespace sf
