#pragma once
// Where an explicit run's wall time goes, phase by phase: what the run summary reports as ns per
// element-cycle (docs/performance.md).
#include <chrono>

namespace sf {

/// Wall time (s) spent in each phase of the explicit steps so far.
struct PhaseTimes {
  double elements = 0.0;   ///< the element forces (internal forces and moments)
  double contact = 0.0;    ///< contact offsets, searches and penalty forces
  double time_step = 0.0;  ///< the stable step (and mass scaling)
  /// everything else in a step: velocities, velocity conditions, positions, tools, external
  /// forces, energy balance
  double nodal = 0.0;
  double output = 0.0;  ///< frames, history rows, progress lines
};

/// Adds the wall time from its construction to its destruction to `total` (s).
class PhaseTimer {
 public:
  explicit PhaseTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~PhaseTimer() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sf
