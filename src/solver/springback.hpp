#pragma once
// Springback after the forming run: the tools are removed and the blank, keeping its stresses and
// plastic history, finds its unloaded shape, by the implicit static step (Newton, SuiteSparse) or
// by the explicit route (the tool forces released slowly, then dynamic relaxation). Frames go on
// in the same results; docs/static-analysis.md.
#include <optional>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "solver/frame_output.hpp"
#include "solver/solution_state.hpp"
#include "solver/u_channel_measures.hpp"

namespace sf {

/// What a springback step reports (summary and summary.json).
struct SpringbackSummary {
  std::string method;          ///< "implicit" or "dynamic_relaxation"
  double wall_seconds = 0.0;   ///< s, the whole springback step
  double max_displacement = 0.0;  ///< mm, largest springback displacement |x - x_formed|
  int max_displacement_node = -1;
  /// Extra holds that removed rigid-body modes: "node 12 (gmsh 13) uz", ...
  std::vector<std::string> added_constraints;

  // implicit
  int increments = 0;             ///< converged increments
  int cuts = 0;                   ///< increments halved after a failure
  int newton_iterations = 0;      ///< over all converged increments
  std::vector<int> iterations_per_increment;
  std::string linear_solver;      ///< "CHOLMOD" or "UMFPACK" (the last factorisation)
  int equations = 0;
  long matrix_nonzeros = 0;
  long factor_nonzeros = 0;
  double fill_ratio = 0.0;
  double tangent_seconds = 0.0;   ///< s, building the tangent stiffness, all iterations
  double analyse_seconds = 0.0;   ///< s, symbolic analyses, all iterations
  double factor_seconds = 0.0;    ///< s, numeric factorisations, all iterations
  double solve_seconds = 0.0;     ///< s, triangular solves, all iterations
  int factorizations = 0;

  // dynamic relaxation
  double release_time = 0.0;      ///< s
  double relaxation_time = 0.0;   ///< s, after the release, until at rest
  long cycles = 0;                ///< explicit cycles of release and relaxation
  double final_kinetic_ratio = 0.0;  ///< kinetic / internal energy at the end
  bool at_rest = false;

  /// The case's U-channel measures, on the formed shape (tools in place) and after springback.
  std::optional<UChannelMeasures> u_channel_formed;
  std::optional<UChannelMeasures> u_channel;
};

/// Runs the case's [springback] from the end-of-forming state `state` (changed to the sprung
/// shape), writing its frames to `output` (may be null). Throws ConvergenceError when the
/// implicit step cannot converge, InstabilityError when the explicit route goes unstable.
SpringbackSummary run_springback(Model& model, SolutionState& state, FrameOutput* output);

}  // namespace sf
