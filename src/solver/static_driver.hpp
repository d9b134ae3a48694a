#pragma once
// A static analysis of the blank under its loads and boundary conditions ([analysis] type =
// "static"): the load curves run over the pseudo-time 0..control.end_time (a load without a curve
// ramps linearly from zero to its value), solved by the implicit static step (linear: one solve;
// nonlinear: Newton increments). docs/static-analysis.md.
#include "model/model.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/run_summary.hpp"

namespace sf {

/// Runs the static analysis, writing a history row per converged increment (time = load factor x
/// end_time) and frames at the control.output_frames pseudo-times (each at the first converged
/// increment at or past it; the initial state and the final one always); the final state goes to
/// `final_state` when given. Throws ConvergenceError when the step cannot converge (after writing
/// the last converged state as a frame), InputError for constraints that leave rigid-body modes
/// free with implicit.rigid_body_modes = "error".
RunSummary run_static(const Model& model, const RunOptions& options,
                      SolutionState* final_state = nullptr);

}  // namespace sf
