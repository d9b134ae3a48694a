#include "solver/frame_observer.hpp"

#include "solver/state_gather.hpp"

namespace sf {

double FrameObserver::bound_step(const SolutionState& s, double dt) {
  return land_on_frames_ ? schedule_.land_on_frame(s.time, dt) : dt;
}

// A history row every history_interval cycles and at every frame (the frame's added mass, time
// step, energies).
bool FrameObserver::after_step(SolutionState& s) {
  const PhaseTimer timer(s.times.output);
  const OutputSchedule::Due due = schedule_.after_step(s.time, s.cycle);
  if (gather_ && (due.history || due.frame)) {
    gather_state_to_root(s);  // every process: the schedule is the same on all
  }
  if (output_ && due.history) {
    output_->append_history(model_, s);
  }
  if (output_ && due.frame) {
    output_->write_frame(model_, s);
    last_frame_time_ = s.time;
  }
  return false;
}

}  // namespace sf
