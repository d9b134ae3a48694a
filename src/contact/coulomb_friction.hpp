#pragma once
// Regularised Coulomb friction of one contact node: an elastic stick spring in the tangent plane
// with a return mapping onto the Coulomb limit, and a slip-speed dependent coefficient.
//
//   mu(v) = mu_d + (mu_s - mu_d) exp(-c |v|)
//
// is the exponential static-to-dynamic decay used by LS-DYNA's contact friction (FS, FD, DC;
// LS-DYNA Keyword User's Manual, *CONTACT) -- quoted from that manual's description, not
// re-checked against the primary source here: grade C.
#include <string_view>

#include "core/types.hpp"

namespace sf {

/// Friction parameters of a contact pair. Units: mm, s, N.
struct FrictionParameters {
  double static_coefficient = 0;   ///< mu_s >= 0 (0: frictionless)
  double dynamic_coefficient = 0;  ///< mu_d, 0 <= mu_d <= mu_s
  double decay = 0;                ///< c >= 0, s/mm: mu falls from mu_s to mu_d as exp(-c |v|)
  /// k_t / k: the tangential (stick) stiffness as a multiple of the node's normal penalty
  /// stiffness, 0 < ratio <= 1. The default 1 gives the stick spring the same frequency as the
  /// normal spring, which the penalty stiffness cap already keeps stable (the normal and
  /// tangential springs act in orthogonal directions, so the node's contact frequency stays
  /// sqrt(max(k, k_t) / m)); a larger k_t would break that cap, a smaller one lets a sticking
  /// node creep elastically by |F_t| / k_t.
  double tangential_stiffness_ratio = 1.0;

  bool active() const { return static_coefficient > 0; }
  /// mu(v) for the slip speed v (mm/s).
  double coefficient(double slip_speed) const;
  /// Throws InputError (naming the tool) unless 0 <= mu_d <= mu_s, c >= 0 and
  /// 0 < tangential_stiffness_ratio <= 1 (all finite).
  void validate(std::string_view tool) const;
};

/// The outcome of one friction update.
struct FrictionStep {
  Vec3 force = Vec3::Zero();  ///< friction force on the blank node, N (in the tangent plane)
  double slip = 0;            ///< plastic (slip) part of the tangential increment, mm, >= 0
  double work = 0;            ///< friction work dissipated in this update, N mm, >= 0
  bool sliding = false;       ///< the trial force exceeded the Coulomb limit
};

/// One friction update of a node in contact (backward-Euler return mapping):
///  1. `stored_force` (the elastic stick force of the previous update, N) is rotated into the
///     tangent plane of `normal` (unit): projected and rescaled to its length, so that a tilting
///     normal keeps it tangent without changing it (dropped if it has no tangential part);
///  2. trial = rotated - k_t du_t, du_t the tangential part of `increment` (mm, the node's
///     displacement relative to the tool over the step);
///  3. limit = mu(|du_t| / dt) * normal_force (dt <= 0: mu_s); if |trial| <= limit the node
///     sticks, else the force is scaled back to the limit (slides) and the slip is
///     (|trial| - limit) / k_t, the work dissipated limit * slip.
/// On return `stored_force` holds the new force. normal_force >= 0 (N), k_t > 0 (N/mm).
/// |force| <= mu * normal_force always. No allocation.
FrictionStep coulomb_friction_update(const FrictionParameters& law, Vec3& stored_force,
                                     const Vec3& normal, const Vec3& increment, double dt,
                                     double normal_force, double k_t);

}  // namespace sf
