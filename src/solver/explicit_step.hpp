#pragma once
// One step of the explicit central-difference scheme, the stepper every explicit driver uses
// (forming, dynamic relaxation, the tests): docs/time-integration.md.
#include "model/model.hpp"
#include "solver/energy_balance.hpp"
#include "solver/initial_state.hpp"
#include "solver/solution_state.hpp"
#include "solver/step_forces.hpp"
#include "solver/time_step_control.hpp"

namespace sf {

/// Advances one central-difference step of size dt (s): velocities, positions, tools, forces and
/// energies (the kinetic energy at the step end, from v(n+1) = v(n+1/2) + dt/2 a(n+1); state.v
/// stays at the half step). dt_previous is the step before (0 on the first step, and after a
/// restart from rest).
void advance_one_step(const Model& model, SolutionState& state, double dt, double dt_previous);

}  // namespace sf
