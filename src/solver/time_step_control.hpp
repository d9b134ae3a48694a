#pragma once
// The stable time step of an explicit run, with mass scaling at fixed nodal momentum.
#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// The stable step (s) of the blank at the current state, with the case's safety factor. With
/// mass scaling on (control.mass_scaling_dt > 0) it first adds mass to every element whose step
/// has fallen below the target, at fixed nodal momentum (state.v and state.omega are lowered; the
/// kinetic energy this removes, less the drop of the half-kick energy, goes to
/// energies.mass_scaling: docs/time-integration.md). Records the step and its limiting
/// element in state (stable_dt, dt_element, min_stable_dt, max_stable_dt). Throws
/// InstabilityError when the added mass passes control.mass_scaling_max_added.
double compute_time_step(const Model& model, SolutionState& state);

/// Throws InstabilityError when a step of dt (s) would not move the time state.time on: a step of
/// 0, one lost in the time's round-off, or not a finite number. A time loop calls it before each
/// step so that it can never cycle in place (build_model refuses such a step at the start; this
/// guards any that arises later). `where` follows the time in the message (" in the springback").
void check_step_advances(const SolutionState& state, double dt, const char* where);

}  // namespace sf
