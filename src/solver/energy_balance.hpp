#pragma once
// The explicit run's energy balance: kinetic and half-kick energies, the trapezoidal work of one
// step, and the blow-up check (docs/time-integration.md).
#include <string_view>

#include "element/shell_forces.hpp"
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// Kinetic energy (N mm) of the velocities as they stand in the state: the initial velocities
/// v(0), which are already at a whole step.
double kinetic_energy(const Model& model, const SolutionState& state);

/// The rate u (mm/s^2, rad/s^2) of node i's half kicks: the force sum times the given inverse
/// mass (1/tonne) and inverse inertia (1/(tonne mm^2)), less the damping on the half-step
/// velocity; zero in the components the constraints hold (docs/time-integration.md).
void half_kick_rate(const Model& model, const SolutionState& state, Eigen::Index i,
                    double inverse_mass, double inverse_inertia, Vec3& u, Vec3& u_omega);

/// The kinetic energy at the step end and the half-kick energy D (N mm).
struct KineticEnergy {
  double kinetic = 0.0;
  double half_kick = 0.0;
};

/// Kinetic energy (N mm) at the end of the step just taken, t(n+1), from the whole-step velocity
/// v(n+1) = v(n+1/2) + dt(n+1/2) / 2 (a(n+1) - c v(n+1/2)), and the half-kick energy D.
KineticEnergy whole_step_kinetic_energy(const Model& model, const SolutionState& state, double dt);

/// Before a step of dt (s) after one of dt_previous: the half-kick energy's reference D(0) on the
/// first step, or D's jump where the step size changes taken out of it.
void update_half_kick_reference(const Model& model, SolutionState& state, double dt,
                                double dt_previous);

/// After the step [time_before, state.time] of dt (s): the work of the internal, external,
/// contact, damping and tool forces by the trapezoidal rule, the element pass's hourglass and
/// plastic work, prescribed_work (N mm) of the velocity conditions, the tools' peak forces and the
/// kinetic energy at the step end, into state.energies.
void account_step_energies(const Model& model, SolutionState& state,
                           const ShellForceResult& elements, double prescribed_work,
                           double time_before, double dt);

/// Throws InstabilityError when the total energy passes control.energy_blowup_ratio times the
/// work supplied (or energy_scale, N mm, if larger: below it the check is silent). `where`
/// follows "energy blow-up" in the message (e.g. " in the springback (dynamic relaxation)");
/// `remedy` ends it unless the damping is past its stability limit.
void check_energy_blowup(const Model& model, const SolutionState& state, double energy_scale,
                         std::string_view where, std::string_view remedy);

}  // namespace sf
