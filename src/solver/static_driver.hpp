#pragma once
// A static analysis of the blank under its loads and boundary conditions ([analysis] type =
// "static"): the load curves run over the pseudo-time 0..control.end_time (a load without a curve
// ramps linearly from zero to its value), solved by the implicit static step (linear: one solve;
// nonlinear: Newton increments). docs/static-analysis.md.
#include "model/model.hpp"
#include "solver/explicit_driver.hpp"
#include "solver/run_summary.hpp"

namespace sf {

/// Runs the static analysis, writing a frame (time = load factor x end_time) and a history row
/// per converged increment; the final state goes to `final_state` when given. Throws
/// ConvergenceError when the step cannot converge, InputError for constraints that leave
/// rigid-body modes free with implicit.rigid_body_modes = "error".
RunSummary run_static(Model& model, const RunOptions& options,
                      SolutionState* final_state = nullptr);

}  // namespace sf
