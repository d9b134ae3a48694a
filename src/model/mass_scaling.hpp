#pragma once
// Selective (per-element) mass scaling to a target time step, and the stable step it leaves.
// See docs/time-integration.md for the semantics and the energy accounting.
#include <span>
#include <vector>

#include "core/exact_sum.hpp"
#include "core/types.hpp"
#include "element/corner_forces.hpp"
#include "element/shell_forces.hpp"
#include "element/shell_mass.hpp"
#include "element/shell_part.hpp"

namespace sf {

/// Mass scaling state of a shell part, structure of arrays over its elements. Set up once by
/// set_up_mass_scaling; afterwards only scale_mass_to_time_step changes it, and only upwards.
struct MassScaling {
  double target_dt = 0.0;  ///< s, the step every element is held at (control.mass_scaling_dt);
                           ///< 0 = mass scaling off
  double safety = 0.9;     ///< -, the time-step safety factor (control.time_step_safety)
  std::vector<double> element_mass;    ///< tonne per element, physical: rho t0 A0
  std::vector<double> inertia_factor;  ///< mm^2 per element, rotational inertia / mass per node
  std::vector<double> density_factor;  ///< - per element, scaled / physical density, >= 1, never
                                       ///< decreases
  std::vector<double> element_dt;      ///< s per element, scratch: critical step at the physical
                                       ///< density (last computed)
  std::vector<double> scaled_dt;       ///< s per element, scratch: its step after the last raise
                                       ///< (safety included)
  std::vector<double> corner_mass;     ///< scratch, kMassCornerWidth per corner slot: what the
                                       ///< last raise added to each element's nodes
  double added_mass = 0.0;             ///< tonne, sum over elements of (density_factor - 1) m_e
                                       ///< (each raise's share summed exactly, then added)
  int scaled_elements = 0;             ///< elements with density_factor > 1

  bool enabled() const { return target_dt > 0.0; }
};

/// What one time-step evaluation found.
struct TimeStepCheck {
  double dt = 0.0;          ///< s, the stable step with the safety factor (after any scaling)
  int element = -1;         ///< the element that limits it
  double mass_added = 0.0;  ///< tonne added in this call
};

/// Relative shortfall below the target tolerated before an element is scaled (again): without it,
/// round-off in the recomputed step of an element already at the target would add mass every cycle.
inline constexpr double kMassScalingTolerance = 1e-9;

/// Fills `scaling` for `part` at the coordinates x and thickness in `state` (the reference
/// configuration): element masses and inertia factors, factors 1, no added mass. target_dt (s) and
/// safety (-) as in the case's control table.
void set_up_mass_scaling(const ShellPart& part, const Matrix3X& x, const ShellState& state,
                         double target_dt, double safety, MassScaling& scaling);

/// What one process's elements added in one raise: exact sums, the same whichever process added
/// what (the caller reduces them over the processes).
struct DensityRaise {
  ExactSum added_mass;    ///< tonne
  ExactSum newly_scaled;  ///< elements scaled for the first time
};

/// Raises the density of every element of `runs` (all elements when empty) whose step at its
/// density, safety x element_dt x sqrt(density_factor), is below target_dt (1 - tolerance), so
/// that its step is target_dt: rho_e = rho (target_dt / (safety dt_e))^2, dt_e the element's step
/// at the physical density (scaling.element_dt). Each element's added mass is shared equally by
/// its nodes, alpha_e times as much rotational inertia (as the lumped mass): written per node to
/// its corner slots of scaling.corner_mass (0 when it added nothing), for add_corner_masses or
/// Domain::add_corner_masses. Its step after the raise goes to scaling.scaled_dt. Only the
/// elements of `runs` are read or written. No allocation.
DensityRaise raise_element_densities(const ShellPart& part, std::span<const ElementRun> runs,
                                     MassScaling& scaling);

/// The stable time step (s, safety included) of `part` at the coordinates x, every element's
/// density raised first where its step is below the target (raise_element_densities), the masses
/// added to the nodes (nodal_mass tonne, rotational_inertia tonne mm^2; nodes: the part's corner
/// lists). One process, all elements: the model's start. Velocities are the caller's business.
TimeStepCheck scale_mass_to_time_step(const ShellPart& part, const NodeCorners& nodes,
                                      const Matrix3X& x, MassScaling& scaling, VectorX& nodal_mass,
                                      VectorX& rotational_inertia);

}  // namespace sf
