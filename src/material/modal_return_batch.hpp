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
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "core/errors.hpp"
#include "material/hardening.hpp"

namespace sf {

/// Largest batch: the most through-thickness points of a shell section.
inline constexpr int kMaxReturnLanes = 9;

/// The points of one batch: inputs (modal weights, trial equivalent stress, plastic strain and
/// flow stress at the start) and outputs (D and the new plastic strain), one lane per point.
struct ModalReturnBatch {
  int n = 0;                        ///< lanes in use
  double A[3][kMaxReturnLanes];     ///< MPa^2, modal weights A_i = lam_i y_i^2
  double phi_tr[kMaxReturnLanes];   ///< MPa, trial equivalent stress
  double eps_n[kMaxReturnLanes];    ///< -, plastic strain at the start
  double sy_n[kMaxReturnLanes];     ///< MPa, flow stress at eps_n
  double slope_n[kMaxReturnLanes];  ///< MPa, its slope
  double D[kMaxReturnLanes];        ///< 1/MPa, out: d_lambda / sigma_eq(n+1)
  double eps[kMaxReturnLanes];      ///< -, out: new plastic strain
};

namespace detail {

// Flow stress and slope at eps for the return's iterate: Swift from the start of the step by its
// binomial series (no pow for the small steps of a return), the other laws directly.
template <class Law>
inline FlowStress iterate_flow_stress(const Law& law, double eps, double eps_n,
                                      const FlowStress& at_n) {
  if constexpr (std::is_same_v<Law, SwiftHardening>) {
    return law.evaluate_near(eps, eps_n, at_n);
  } else {
    return law.evaluate(eps);
  }
}

[[noreturn]] inline void throw_no_convergence(const char* name, double phi_tr) {
  throw InstabilityError(std::string(name) +
                         ": return mapping did not converge (trial equivalent stress " +
                         std::to_string(phi_tr) + " MPa)");
}

}  // namespace detail

/// Solves r(D) = 0 for every lane of `b` (the first kModes modes carry weight; a J2 return has
/// two, its third weight being zero), relative tolerance 1e-10 on the yield condition, at most
/// 100 iterations (then InstabilityError naming `name`: only possible with non-finite input).
template <int kModes, class Law>
inline void solve_modal_return(ModalReturnBatch& b, const double (&lam)[3], const Law& law,
                               const char* name) {
  constexpr int L = kMaxReturnLanes;
  const int n = b.n;
  const double grow = 1.0 / std::max({lam[0], lam[1], lam[2]});
  double D[L], lo[L], hi[L], phi[L], eps[L], sy[L], slope[L], c[3][L];
  bool active[L];
  for (int l = 0; l < n; ++l) {
    D[l] = 0.0;
    lo[l] = 0.0;
    hi[l] = std::numeric_limits<double>::infinity();
    phi[l] = b.phi_tr[l];
    eps[l] = b.eps_n[l];
    sy[l] = b.sy_n[l];  // the first pass reuses the trial check's evaluation (D = 0)
    slope[l] = b.slope_n[l];
    for (int i = 0; i < kModes; ++i) {
      c[i][l] = 1.0;
    }
    active[l] = true;
  }
  int remaining = n;
  for (int it = 0; it < 100; ++it) {
    for (int l = 0; l < n; ++l) {
      if (!active[l]) {
        continue;
      }
      const double r = phi[l] - sy[l];
      if (std::abs(r) <= 1e-10 * sy[l]) {
        b.D[l] = D[l];
        b.eps[l] = eps[l];
        active[l] = false;
        --remaining;
        continue;
      }
      (r > 0.0 ? lo[l] : hi[l]) = D[l];
      double s0 = 0.0;
      double s1 = 0.0;
      for (int i = 0; i < kModes; ++i) {
        const double a3 = b.A[i][l] * c[i][l] * c[i][l] * c[i][l];
        s0 += a3;
        s1 += a3 * lam[i];
      }
      // Newton step; the first one (from D = 0) is replaced by the radial-return estimate
      // D = (phi_tr - sigma_y) / (lam_eff sigma_y + sigma_y' phi_tr), lam_eff = S1/S0, which is
      // the exact root when one mode carries the stress and the hardening is linear, and
      // otherwise saves one or two iterations.
      double next = it == 0 ? r / (s1 / s0 * sy[l] + slope[l] * phi[l])
                            : D[l] - r / (-(s1 + slope[l] * s0) / phi[l]);
      if (!(next > lo[l] && next < hi[l])) {  // Newton left the bracket (or is not finite)
        next = std::isfinite(hi[l]) ? 0.5 * (lo[l] + hi[l]) : 2.0 * lo[l] + grow;
      }
      D[l] = next;
      double phi2 = 0.0;
      for (int i = 0; i < kModes; ++i) {
        c[i][l] = 1.0 / (1.0 + lam[i] * next);
        phi2 += b.A[i][l] * c[i][l] * c[i][l];
      }
      phi[l] = std::sqrt(phi2);
      eps[l] = b.eps_n[l] + next * phi[l];
      const FlowStress h =
          detail::iterate_flow_stress(law, eps[l], b.eps_n[l], FlowStress{b.sy_n[l], b.slope_n[l]});
      sy[l] = h.stress;
      slope[l] = h.slope;
    }
    if (remaining == 0) {
      return;
    }
  }
  for (int l = 0; l < n; ++l) {
    if (active[l]) {
      detail::throw_no_convergence(name, b.phi_tr[l]);
    }
  }
}

}  // namespace sf
