#pragma once
// The progress line of a long run: cycle, time, stroke %, time step, kinetic/internal energy ratio,
// and the estimated time to go.
#include <chrono>

#include "model/model.hpp"
#include "solver/solution_state.hpp"

namespace sf {

class Progress {
 public:
  /// interval_cycles > 0: a line every that many cycles; 0: about every 2 s of wall time.
  Progress(const Model& model, int interval_cycles);
  /// Prints a line when one is due (or always when `final`).
  void report(const Model& model, const SolutionState& state, bool final);

 private:
  int interval_cycles_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace sf
