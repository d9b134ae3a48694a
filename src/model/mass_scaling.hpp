#pragma once
// Selective (per-element) mass scaling to a target time step, and the stable step it leaves.
// See docs/time-integration.md for the semantics and the energy accounting.
#include <vector>

#include "core/types.hpp"
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
  double added_mass = 0.0;             ///< tonne, sum over elements of (density_factor - 1) m_e
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

/// The stable time step (s, safety included) of `part` at the coordinates x. With scaling enabled,
/// first raises the density of every element whose step is below target_dt (1 - tolerance) so
/// that its step is target_dt: rho_e = rho (target_dt / (safety dt_e))^2 with dt_e the element's
/// step at the physical density. The element's added mass is spread equally on its four nodes,
/// into nodal_mass (tonne) and rotational_inertia (tonne mm^2), alpha_e times as much inertia as
/// mass (as the lumped mass does). Velocities are the caller's business (the explicit driver keeps
/// the nodal momentum). No allocation.
TimeStepCheck scale_mass_to_time_step(const ShellPart& part, const Matrix3X& x,
                                      MassScaling& scaling, VectorX& nodal_mass,
                                      VectorX& rotational_inertia);

/// The same from the elements' critical steps already in scaling.element_dt (at the physical
/// density, e.g. from the element force pass: compute_shell_internal_forces) with `physical`
/// their smallest and its element.
TimeStepCheck scale_mass_to_element_steps(const ShellPart& part, const StableStep& physical,
                                          MassScaling& scaling, VectorX& nodal_mass,
                                          VectorX& rotational_inertia);

}  // namespace sf
