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

/// Runs the model from time 0 to its end time, writing frames and history as it goes. Throws
/// InstabilityError (after writing what it can) when the run goes unstable.
RunSummary run_explicit(Model& model, const RunOptions& options);

/// One step's worth of the loop's phases, public so tests can drive a model cycle by cycle.
SolutionState make_initial_state(const Model& model);
/// Internal and contact forces at the current state (state.x, state.v, dt); returns the hourglass
/// power (N mm/s).
double compute_forces(Model& model, SolutionState& state, double dt);
/// Advances one central-difference step of size dt (s): velocities, positions, tools, forces and
/// energies. dt_previous is the step before (0 on the first step).
void advance_one_step(Model& model, SolutionState& state, double dt, double dt_previous);
/// The stable step (s) of the blank at the current state, with the case's safety factor.
double compute_time_step(const Model& model, const SolutionState& state);

}  // namespace sf
