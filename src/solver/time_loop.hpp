#pragma once
// The one explicit time loop (shared/DESIGN.md R9): forming, every operation of the press line
// and springback by dynamic relaxation step the state the same way, and what differs between
// them (when to stop, where a step must land, output, progress, checkpoints, stop requests,
// kinetic damping) are observers of the loop.
#include <limits>
#include <span>
#include <string_view>

#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

/// Something the loop calls around every step.
class LoopObserver {
 public:
  virtual ~LoopObserver() = default;
  LoopObserver() = default;
  LoopObserver(const LoopObserver&) = delete;
  LoopObserver& operator=(const LoopObserver&) = delete;

  /// Before a step: true ends the loop there (the step is not taken).
  virtual bool before_step(SolutionState& /*s*/) { return false; }
  /// s, the step to take instead of the stable one `dt` (a shorter one lands on a time).
  virtual double bound_step(const SolutionState& /*s*/, double dt) { return dt; }
  /// After a step: true ends the loop after it (every observer still sees the step).
  virtual bool after_step(SolutionState& s) = 0;
};

/// The loop's own checks of every step, and how their messages name the loop.
struct LoopChecks {
  const char* where = "";  ///< appended to a message: "" or " in the springback"
  /// N mm, the energy below which the blow-up check is silent
  double energy_scale = 0.0;
  std::string_view blowup_where;   ///< check_energy_blowup's `where`
  std::string_view blowup_remedy;  ///< and its remedy
};

/// Takes steps of the stable size (bounded by the observers) until an observer ends the loop.
/// `dt_previous` (s) is the step before the first one (0 before a run's first step); it is kept
/// up to date. Throws InstabilityError when the step collapses to 1e-3 of the model's initial
/// step, cannot advance the time, or the energy blows up (the observers write what they keep).
void run_time_loop(const Model& model, SolutionState& s, double& dt_previous,
                   const LoopChecks& checks, std::span<LoopObserver* const> observers);

}  // namespace sf
