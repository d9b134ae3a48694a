#pragma once
// Springback after the forming run: the tools are removed and the blank, keeping its stresses and
// plastic history, finds its unloaded shape, by the implicit static step (Newton, SuiteSparse) or
// by the explicit route (the tool forces released slowly, then dynamic relaxation). Frames go on
// in the same results; docs/static-analysis.md.
#include <optional>
#include <string>

#include "implicit/static_step.hpp"
#include "model/model.hpp"
#include "solver/dynamic_relaxation.hpp"
#include "solver/frame_output.hpp"
#include "solver/solution_state.hpp"
#include "solver/u_channel_measures.hpp"

namespace sf {

/// What a springback step reports (summary and summary.json).
struct SpringbackSummary {
  std::string method;             ///< "implicit" or "dynamic_relaxation"
  double wall_seconds = 0.0;      ///< s, the whole springback step
  double max_displacement = 0.0;  ///< mm, largest springback displacement |x - x_formed|
  int max_displacement_node = -1;
  std::optional<ImplicitStepSummary> implicit;        ///< method implicit
  std::optional<DynamicRelaxationResult> relaxation;  ///< method dynamic_relaxation
  /// The case's U-channel measures, on the formed shape (tools in place) and after springback.
  std::optional<UChannelMeasures> u_channel_formed;
  std::optional<UChannelMeasures> u_channel;
};

/// Runs the case's [springback] from the end-of-forming state `state` (changed to the sprung
/// shape), writing its frames to `output` (may be null). Throws ConvergenceError when the
/// implicit step cannot converge, InstabilityError when the explicit route goes unstable.
SpringbackSummary run_springback(const Model& model, SolutionState& state, FrameOutput* output);

/// The implicit method: the blank's internal forces at the end of forming are the tool forces'
/// reactions; they are released, (1 - lambda) of them applied as lambda goes 0 -> 1, by the
/// static step, each converged increment written as a frame at time t_end + lambda x the frame
/// interval. Rigid-body modes the case's constraints leave free are held automatically (or
/// reported, as [implicit] asks).
ImplicitStepSummary run_implicit_springback(const Model& model, SolutionState& state,
                                            FrameOutput* output);

}  // namespace sf
