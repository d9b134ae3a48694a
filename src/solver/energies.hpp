#pragma once
// Energy accounting of an explicit run (N mm = mJ in the forming units).

namespace sf {

struct Energies {
  /// Translational + rotational, at the step end t(n+1): from the whole-step velocity v(n+1) =
  /// v(n+1/2) + dt/2 a(n+1) (docs/time-integration.md)
  double kinetic = 0.0;
  double internal = 0.0;  ///< work of the element forces, hourglass work excluded
  /// Work of the hourglass forces (Belytschko-Tsay) or of the physical stabilisation
  /// (assumed strain, where it is elastic energy of the stabilised modes).
  double hourglass = 0.0;
  /// Work done against the contact forces, accumulated each step by the trapezoidal rule (the
  /// sliding energy of LS-DYNA): dE = -1/2 sum_i (fc_i(n) + fc_i(n+1)) . (x_i(n+1) - x_i(n))
  /// - sum_tools 1/2 (F_t(n) + F_t(n+1)) . (u_t(n+1) - u_t(n)), fc the contact force on blank
  /// node i, F_t the blank's force on tool t, u_t the tool's displacement. For frictionless
  /// penalty contact it equals the spring energy sum 1/2 k g^2 up to the trapezoidal rule's error;
  /// friction and non-gradient normals make it differ (docs/time-integration.md).
  double contact = 0.0;
  double damping = 0.0;        ///< dissipated by mass-proportional damping
  double external_work = 0.0;  ///< work done on the blank by the tools, loads and prescribed motion
  double initial_kinetic = 0.0;  ///< kinetic energy of the initial velocities
  /// Kinetic energy taken out by mass added during the run: mass is added at fixed nodal momentum,
  /// which lowers the velocity by r = m_old / m_new; per node (1 - r) m_old (|v(n)|^2 - |dt/2
  /// a(n)|^2) / 2 (v(n) the whole-step velocity, a(n) the acceleration at the old mass, dt the
  /// coming step): the drop of the kinetic energy less that of the half-kick energy, the
  /// central-difference form of the drop (see docs/time-integration.md).
  double mass_scaling = 0.0;
  /// Plastic dissipation at the integration points. Informational: it is PART of `internal`
  /// (internal = elastic energy + plastic work), not a term of its own in the balance.
  double plastic_work = 0.0;
  /// Work dissipated by Coulomb friction (slip times the friction force). Informational: it is
  /// PART of `contact` (the work done against all contact forces), not a term of its own.
  double friction_work = 0.0;
  /// Work dissipated by slip across the drawbead lines (their restraint times the slip).
  /// Informational: PART of `contact` (the bead forces are contact forces), like friction_work.
  double drawbead_work = 0.0;
  /// The half-kick energy D = 1/2 sum m |dt/2 u|^2 (translations and rotations; u the
  /// acceleration of the next half kick, dt the step just taken) at the step end: the
  /// central-difference scheme keeps total - supplied = D - D_ref exactly, for any forces, so D
  /// is the scheme's own O(dt^2) term of the balance, not an energy of the model
  /// (docs/time-integration.md). It is large only when the highest modes carry energy (a blow at
  /// one node).
  double half_kick = 0.0;
  /// N mm, D at the first step, less D's jumps where the step size changed (D scales with dt^2).
  double half_kick_reference = 0.0;

  /// D - D_ref, the term the balance takes out of the total (history `half_kick_energy`).
  double half_kick_change() const { return half_kick - half_kick_reference; }

  double total() const { return kinetic + internal + hourglass + contact + damping + mass_scaling; }
  /// What the total must equal: the work put in plus the initial kinetic energy.
  double supplied() const { return external_work + initial_kinetic; }
  /// (total - (D - D_ref) - supplied) relative to the larger of total and supplied; 0 when
  /// nothing has happened.
  double balance_error() const;
  /// kinetic / internal, the quasi-static check of a forming run (0 while nothing is strained).
  double kinetic_ratio() const {
    return internal + hourglass > 0.0 ? kinetic / (internal + hourglass) : 0.0;
  }
};

inline double Energies::balance_error() const {
  const double scale = supplied() > total() ? supplied() : total();
  if (scale <= 0.0) {
    return 0.0;
  }
  return (total() - half_kick_change() - supplied()) / scale;
}

}  // namespace sf
