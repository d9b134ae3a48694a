#pragma once
// The explicit central-difference time loop.
#include <filesystem>
#include <functional>

#include "model/model.hpp"
#include "solver/run_summary.hpp"
#include "solver/solution_state.hpp"

namespace sf {

struct RunOptions {
  std::filesystem::path output_directory;  ///< where results.h5 and the .xdmf files go
  bool write_results = true;
};

/// Runs the model from time 0 to its end time, writing frames and history as it goes, then the
/// case's springback if it has one; the final state goes to `final_state` when given. Throws
/// InstabilityError (after writing what it can) when the run goes unstable, ConvergenceError when
/// an implicit springback cannot converge.
RunSummary run_explicit(Model& model, const RunOptions& options,
                        SolutionState* final_state = nullptr);

/// One step's worth of the loop's phases, public so tests can drive a model cycle by cycle.
SolutionState make_initial_state(const Model& model);
/// Internal and contact forces at the current state (state.x, state.v, dt); returns the element
/// pass's hourglass power (N mm/s), stress work and plastic work (N mm).
ShellForceResult compute_forces(Model& model, SolutionState& state, double dt);
/// Advances one central-difference step of size dt (s): velocities, positions, tools, forces and
/// energies (the kinetic energy at the step end, from v(n+1) = v(n+1/2) + dt/2 a(n+1); state.v
/// stays at the half step). dt_previous is the step before (0 on the first step).
void advance_one_step(Model& model, SolutionState& state, double dt, double dt_previous);
/// The stable step (s) of the blank at the current state, with the case's safety factor. With
/// mass scaling on (control.mass_scaling_dt > 0) it first adds mass to every element whose step
/// has fallen below the target, at fixed nodal momentum (state.v and state.omega are lowered; the
/// kinetic energy this removes, less the drop of the half-kick energy, goes to
/// energies.mass_scaling: docs/time-integration.md). Records the step and its limiting
/// element in state (stable_dt, dt_element, min_stable_dt, max_stable_dt). Throws
/// InstabilityError when the added mass passes control.mass_scaling_max_added.
double compute_time_step(Model& model, SolutionState& state);

}  // namespace sf
