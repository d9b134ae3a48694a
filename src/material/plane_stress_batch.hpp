#pragma once
// The update of a batch of integration points of one plane-stress law (the points of one shell
// section; one point for the single-point API of plane_stress.hpp): elastic predictor, yield
// check against the point's stored flow stress, and the modal return of the points that yield,
// solved together (modal_return_batch.hpp). Inline, so that the element loops carry no call per
// point and no result returned by value through memory.
#include <type_traits>
#include <variant>

#include "core/types.hpp"
#include "material/hardening.hpp"
#include "material/material_failure.hpp"
#include "material/modal_return_batch.hpp"
#include "material/plane_stress_kernels.hpp"

namespace sf {

/// Per point, the flow stress (MPa) at the plastic strain it belongs to, so that a yield check
/// needs no hardening evaluation (a Swift law: no pow) while the plastic strain is unchanged. A
/// point whose `at` differs from its plastic strain (never evaluated, or its strain set from
/// outside) is evaluated and stored again. Null pointers: no store, every check evaluates.
struct FlowStressCache {
  double* stress = nullptr;  ///< MPa, per point
  double* at = nullptr;      ///< -, the plastic strain of `stress`, per point
};

namespace detail {

// Flow stress and slope at eps from a known flow stress there: the slope of a Swift law is
// n sigma_y / (eps0 + eps), as its evaluate forms it, so no pow; linear hardening has a constant
// slope; the other laws are evaluated.
template <class Law>
inline FlowStress flow_stress_from(const Law& law, double eps, double stress) {
  if constexpr (std::is_same_v<Law, SwiftHardening>) {
    return {stress, law.n * stress / (law.eps0 + eps)};
  } else if constexpr (std::is_same_v<Law, LinearHardening>) {
    return {stress, law.H};
  } else {
    return law.evaluate(eps);
  }
}

template <class Kernel, class Law>
inline bool update_points_with(const Kernel& k, const Law& law, int n, const Vec3* old_stress,
                               const double* eps_n, const Vec3* d_strain, FlowStressCache cache,
                               PlaneStressUpdate* out, MaterialFailure& failure) {
  ModalReturnBatch b;
  b.n = 0;
  int point[kMaxReturnLanes];
  Vec3 trial[kMaxReturnLanes];
  for (int p = 0; p < n; ++p) {
    const Vec3 tr = elastic_trial(k.E, k.nu, old_stress[p], d_strain[p]);
    const double measure = k.measure(tr);  // squared equivalent stress
    if (!std::isfinite(measure)) {
      failure = {MaterialFailure::Kind::non_finite_trial_stress, Kernel::kName};
      return false;
    }
    const bool stored = cache.stress && cache.at[p] == eps_n[p];
    FlowStress h0 = stored ? FlowStress{cache.stress[p], 0.0} : law.evaluate(eps_n[p]);
    if (!stored && cache.stress) {
      cache.stress[p] = h0.stress;
      cache.at[p] = eps_n[p];
    }
    // Squares are compared: no sqrt when elastic.
    if (measure <= h0.stress * h0.stress) {
      out[p] = {tr, eps_n[p],
                through_thickness_increment(k.E, k.nu, d_strain[p], old_stress[p], tr), false};
      continue;
    }
    if (stored) {
      h0 = flow_stress_from(law, eps_n[p], h0.stress);
    }
    const int l = b.n++;
    double A[3];
    k.weights(tr, A);
    for (int i = 0; i < 3; ++i) {
      b.A[i][l] = A[i];
    }
    b.phi_tr[l] = std::sqrt(measure);
    b.eps_n[l] = eps_n[p];
    b.sy_n[l] = h0.stress;
    b.slope_n[l] = h0.slope;
    point[l] = p;
    trial[l] = tr;
  }
  if (b.n == 0) {
    return true;
  }
  if (const int l = solve_modal_return<Kernel::kModes, Law>(b, k.lam, law); l >= 0) {
    failure = {MaterialFailure::Kind::return_not_converged, Kernel::kName, {b.phi_tr[l]}};
    return false;
  }
  for (int l = 0; l < b.n; ++l) {
    const int p = point[l];
    const Vec3 s = k.returned_stress(trial[l], b.D[l]);
    // Plastic work with the mid-step stress.
    const double work = 0.5 * (old_stress[p] + s).dot(k.plastic_strain(s, b.D[l]));
    out[p] = {s, b.eps[l], through_thickness_increment(k.E, k.nu, d_strain[p], old_stress[p], s),
              true, work};
    if (cache.stress) {
      // The flow stress the return converged on, for the point's next check.
      cache.stress[p] = b.sy[l];
      cache.at[p] = b.eps[l];
    }
  }
  return true;
}

}  // namespace detail

/// Updates n points (n <= kMaxReturnLanes) for the strain increments d_strain[p] = (d_exx, d_eyy,
/// d_gxy) from old_stress[p] and plastic strain eps_n[p]; results in out[p]. Returns false when a
/// return mapping fails (non-finite input), with `failure` saying how; out is then not to be
/// used.
template <class Kernel>
[[nodiscard]] inline bool update_points(const Kernel& k, int n, const Vec3* old_stress,
                                        const double* eps_n, const Vec3* d_strain,
                                        FlowStressCache cache, PlaneStressUpdate* out,
                                        MaterialFailure& failure) {
  return std::visit(
      [&](const auto& law) {
        return detail::update_points_with(k, law, n, old_stress, eps_n, d_strain, cache, out,
                                          failure);
      },
      *k.hardening);
}

/// Linear elasticity: the predictor, no check.
[[nodiscard]] inline bool update_points(const ElasticKernel& k, int n, const Vec3* old_stress,
                                        const double* eps_n, const Vec3* d_strain,
                                        FlowStressCache /*cache*/, PlaneStressUpdate* out,
                                        MaterialFailure& /*failure*/) {
  for (int p = 0; p < n; ++p) {
    const Vec3 s = elastic_trial(k.E, k.nu, old_stress[p], d_strain[p]);
    out[p] = {s, eps_n[p], through_thickness_increment(k.E, k.nu, d_strain[p], old_stress[p], s),
              false};
  }
  return true;
}

}  // namespace sf
