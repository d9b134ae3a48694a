#pragma once
// The consistency equation of the closed-point return in modal form, solved for a batch of points
// at once (the yielding points of one shell element's section). Each point is one lane; the lanes
// advance together, one Newton iteration per pass, and a lane that has converged is masked out.
// Why a batch: one point's Newton iteration is a chain of divisions and a square root that the
// processor cannot overlap; the chains of independent points overlap (and fill SIMD lanes where
// the compiler packs them). Every lane performs exactly the operations of the one-point return,
// in the same order, so the result does not depend on the batch it was solved in.
//
// With C^-1 and the yield matrix P diagonalised together (Q^T C^-1 Q = I, Q^T P Q = diag(lam)),
// the backward-Euler stress is a scaling of the trial stress's modal coordinates y_i by
// c_i = 1 / (1 + lam_i D), D = d_lambda / sigma_eq(n+1), and
//   phi(D)^2 = sigma_eq^2 = sum_i A_i c_i^2,   A_i = lam_i y_i^2.
// Consistency r(D) = phi(D) - sigma_y(eps_n + D phi(D)) = 0 (d eps_p = d_lambda = D phi by
// plastic-work equivalence, sigma . d_eps^p = d_lambda sigma_eq). With
// S0 = sum A_i c_i^3, S1 = sum A_i lam_i c_i^3: phi' = -S1/phi, d(D phi)/dD = S0/phi > 0, so
// r' = -(S1 + sigma_y' S0)/phi < 0 for a non-decreasing flow stress: one root, bracketed Newton.
#include "material/hardening.hpp"

namespace sf {

/// Lanes are processed in blocks of this many (the widest SIMD registers the kernel is built for
/// hold 4 doubles); a batch is padded to whole blocks with idle lanes.
inline constexpr int kReturnBlock = 4;
/// Lanes of a batch: the most through-thickness points of a shell section (9), padded to whole
/// blocks.
inline constexpr int kMaxReturnLanes = 12;

/// The points of one batch: inputs (modal weights, trial equivalent stress, plastic strain and
/// flow stress at the start) and outputs (D and the new plastic strain), one lane per point.
struct ModalReturnBatch {
  int n = 0;                        ///< lanes in use (<= 9)
  double A[3][kMaxReturnLanes];     ///< MPa^2, modal weights A_i = lam_i y_i^2
  double phi_tr[kMaxReturnLanes];   ///< MPa, trial equivalent stress
  double eps_n[kMaxReturnLanes];    ///< -, plastic strain at the start
  double sy_n[kMaxReturnLanes];     ///< MPa, flow stress at eps_n
  double slope_n[kMaxReturnLanes];  ///< MPa, its slope
  double D[kMaxReturnLanes];        ///< 1/MPa, out: d_lambda / sigma_eq(n+1)
  double eps[kMaxReturnLanes];      ///< -, out: new plastic strain
  /// MPa, out: the flow stress at eps the return converged on (a Swift law's by the binomial
  /// series from sy_n where the step is small: SwiftHardening::evaluate_near), so that its next
  /// yield check needs no evaluation (no pow).
  double sy[kMaxReturnLanes];
};

/// Solves r(D) = 0 for every lane of `b` (the first kModes modes carry weight; a J2 return has
/// two, its third weight being zero), relative tolerance 1e-10 on the yield condition, at most
/// 100 iterations. Returns -1, or the first lane that did not converge (only possible with
/// non-finite input).
/// Instantiated for kModes = 2, 3 and every hardening law (modal_return_batch.cpp), compiled for
/// generic x86-64 and for x86-64-v3 (AVX2), chosen at run time; both give the same bits.
template <int kModes, class Law>
int solve_modal_return(ModalReturnBatch& b, const double (&lam)[3], const Law& law);

}  // namespace sf
