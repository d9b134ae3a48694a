#include "material/modal_return_batch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "core/simd_block.hpp"

// Compiled twice, for generic x86-64 and for x86-64-v3 (AVX2: 4 lanes per instruction), the
// variant chosen at run time by the processor (GCC function multiversioning). The build compiles
// with -ffp-contract=off, so the x86-64-v3 variant fuses no multiply-add: both variants perform
// the same correctly rounded operations per lane and give the same bits.
// SF_NO_MULTIVERSIONING (a test switch) builds the generic variant only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(SF_NO_MULTIVERSIONING)
#define SF_RETURN_CLONES __attribute__((target_clones("default", "arch=x86-64-v3")))
#else
#define SF_RETURN_CLONES
#endif

namespace sf {

namespace {

constexpr int L = kMaxReturnLanes;
constexpr int B = kReturnBlock;
static_assert(kReturnBlock == kBlockLanes);
constexpr int kBlocks = L / B;

using Mask = BlockMask;

// The iterates of every lane. A lane is active until it converges; idle lanes (converged, or
// padding beyond the batch) compute along without effect, so that each pass is straight-line
// SIMD code over whole blocks.
struct Lanes {
  Block D[kBlocks], lo[kBlocks], hi[kBlocks], phi[kBlocks], eps[kBlocks], sy[kBlocks],
      slope[kBlocks], r[kBlocks], c[3][kBlocks];
  Mask active[kBlocks];
};

// Residuals; lanes that meet the tolerance store their result and go idle. Returns the number
// of lanes still active.
SF_BLOCK_INLINE int check_convergence(Lanes& s, ModalReturnBatch& b, int nb) {
  int remaining = 0;
  for (int k = 0; k < nb; ++k) {
    const Block r = s.phi[k] - s.sy[k];
    const Mask converged = block_abs(r) <= 1e-10 * s.sy[k];
    const Mask done = s.active[k] & converged;
    store_block(b.D + B * k, done ? s.D[k] : load_block(b.D + B * k));
    store_block(b.eps + B * k, done ? s.eps[k] : load_block(b.eps + B * k));
    store_block(b.sy + B * k, done ? s.sy[k] : load_block(b.sy + B * k));
    s.active[k] &= ~converged;
    s.r[k] = r;
    for (int j = 0; j < B; ++j) {
      remaining += s.active[k][j] != 0;
    }
  }
  return remaining;
}

// One Newton step of every active lane, then the new modal scalings, equivalent stress and plastic
// strain. The first step (from D = 0) is the radial-return estimate D = (phi_tr - sigma_y) /
// (lam_eff sigma_y + sigma_y' phi_tr), lam_eff = S1/S0, which is the exact root when one mode
// carries the stress and the hardening is linear, and otherwise saves one or two iterations.
template <int kModes, bool kFirst>
SF_BLOCK_INLINE void newton_step(Lanes& s, const ModalReturnBatch& b, const double (&lam)[3],
                                 double grow, int nb) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < nb; ++k) {
    const Mask active = s.active[k];
    const Block r = s.r[k];
    const Block D = s.D[k];
    const Mask positive = r > 0.0;
    s.lo[k] = (active & positive) ? D : s.lo[k];
    s.hi[k] = (active & ~positive) ? D : s.hi[k];
    Block A[kModes];
    Block s0 = {};
    Block s1 = {};
    for (int i = 0; i < kModes; ++i) {
      A[i] = load_block(b.A[i] + B * k);
      const Block a3 = A[i] * s.c[i][k] * s.c[i][k] * s.c[i][k];
      s0 += a3;
      s1 += a3 * lam[i];
    }
    Block next;
    if constexpr (kFirst) {
      next = r / (s1 / s0 * s.sy[k] + s.slope[k] * s.phi[k]);
    } else {
      next = D - r / (-(s1 + s.slope[k] * s0) / s.phi[k]);
    }
    // Newton left the bracket (or is not finite): bisect, or grow while there is no upper bound.
    const Block lo = s.lo[k];
    const Block hi = s.hi[k];
    const Block fallback = block_abs(hi) < kInf ? 0.5 * (lo + hi) : 2.0 * lo + grow;
    next = ((next > lo) & (next < hi)) ? next : fallback;
    const Block d_new = active ? next : D;
    s.D[k] = d_new;
    Block phi2 = {};
    for (int i = 0; i < kModes; ++i) {
      const Block c = 1.0 / (1.0 + lam[i] * d_new);
      s.c[i][k] = c;
      phi2 += A[i] * c * c;
    }
    s.phi[k] = block_sqrt(phi2);
    s.eps[k] = load_block(b.eps_n + B * k) + d_new * s.phi[k];
  }
}

// Flow stress and slope at every active lane's new plastic strain. Swift: from the start of the
// step by the binomial series (no pow), or evaluated where the step is too large for the series.
template <class Law>
SF_BLOCK_INLINE void update_flow_stress(Lanes& s, const ModalReturnBatch& b, const Law& law,
                                        int nb) {
  if constexpr (std::is_same_v<Law, SwiftHardening>) {
    for (int k = 0; k < nb; ++k) {
      const Block x = law.near_ratio(s.eps[k], load_block(b.eps_n + B * k));
      const Block sy = law.near_stress(x, load_block(b.sy_n + B * k));
      s.sy[k] = sy;
      s.slope[k] = law.n * sy / (law.eps0 + s.eps[k]);
      const Mask far = s.active[k] & ~(block_abs(x) <= SwiftHardening::kNearRange);
      for (int j = 0; j < B; ++j) {
        if (far[j]) {
          const FlowStress h = law.evaluate(s.eps[k][j]);
          s.sy[k][j] = h.stress;
          s.slope[k][j] = h.slope;
        }
      }
    }
  } else {
    for (int k = 0; k < nb; ++k) {
      for (int j = 0; j < B; ++j) {
        if (s.active[k][j]) {
          const FlowStress h = law.evaluate(s.eps[k][j]);
          s.sy[k][j] = h.stress;
          s.slope[k][j] = h.slope;
        }
      }
    }
  }
}

// The lanes at D = 0; padding lanes idle with harmless values.
SF_BLOCK_INLINE void start_lanes(Lanes& s, ModalReturnBatch& b, int nb) {
  for (int l = b.n; l < nb * B; ++l) {
    for (int i = 0; i < 3; ++i) {
      b.A[i][l] = 0.0;
    }
    b.phi_tr[l] = 0.0;
    b.eps_n[l] = 0.0;
    b.sy_n[l] = 1.0;
    b.slope_n[l] = 0.0;
  }
  for (int k = 0; k < nb; ++k) {
    s.D[k] = Block{};
    s.lo[k] = Block{};
    s.hi[k] = Block{} + std::numeric_limits<double>::infinity();
    s.phi[k] = load_block(b.phi_tr + B * k);
    s.eps[k] = load_block(b.eps_n + B * k);
    s.sy[k] =
        load_block(b.sy_n + B * k);  // the first pass reuses the trial check's evaluation (D = 0)
    s.slope[k] = load_block(b.slope_n + B * k);
    for (int i = 0; i < 3; ++i) {
      s.c[i][k] = Block{} + 1.0;
    }
    for (int j = 0; j < B; ++j) {
      s.active[k][j] = B * k + j < b.n ? -1 : 0;
    }
    store_block(b.D + B * k, Block{});
    store_block(b.eps + B * k, Block{});
    store_block(b.sy + B * k, Block{});
  }
}

}  // namespace

template <int kModes, class Law>
SF_RETURN_CLONES int solve_modal_return(ModalReturnBatch& b, const double (&lam)[3],
                                        const Law& law) {
  const int nb = (b.n + B - 1) / B;
  const double grow = 1.0 / std::max({lam[0], lam[1], lam[2]});
  Lanes s;
  start_lanes(s, b, nb);
  for (int it = 0; it < 100; ++it) {
    if (check_convergence(s, b, nb) == 0) {
      return -1;
    }
    if (it == 0) {
      newton_step<kModes, true>(s, b, lam, grow, nb);
    } else {
      newton_step<kModes, false>(s, b, lam, grow, nb);
    }
    update_flow_stress(s, b, law, nb);
  }
  for (int l = 0; l < b.n; ++l) {
    if (s.active[l / B][l % B]) {
      return l;
    }
  }
  return -1;
}

#define SF_INSTANTIATE_RETURN(LAW)                                                            \
  template int solve_modal_return<2, LAW>(ModalReturnBatch&, const double(&)[3], const LAW&); \
  template int solve_modal_return<3, LAW>(ModalReturnBatch&, const double(&)[3], const LAW&);
SF_INSTANTIATE_RETURN(SwiftHardening)
SF_INSTANTIATE_RETURN(LinearHardening)
SF_INSTANTIATE_RETURN(VoceHardening)
SF_INSTANTIATE_RETURN(LudwikHardening)
SF_INSTANTIATE_RETURN(TabulatedHardening)
SF_INSTANTIATE_RETURN(HockettSherbyHardening)
SF_INSTANTIATE_RETURN(SwiftVoceHardening)
#undef SF_INSTANTIATE_RETURN

}  // namespace sf
