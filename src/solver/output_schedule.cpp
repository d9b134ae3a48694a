#include "solver/output_schedule.hpp"

#include <algorithm>

namespace sf {
namespace {
// Relative slack on the frame times: a step that ends within round-off of a frame time is on it.
constexpr double kTimeSlack = 1e-12;
}  // namespace

OutputSchedule::OutputSchedule(double start, double duration, int frames, int history_interval)
    : start_(start),
      interval_(duration / std::max(frames, 1)),
      end_(start + duration),
      frames_(std::max(frames, 1)),
      history_interval_(std::max(history_interval, 1)) {}

OutputSchedule OutputSchedule::every_step() {
  OutputSchedule s;
  s.every_step_ = true;
  return s;
}

double OutputSchedule::next_frame_time() const {
  if (next_ >= frames_) {
    return end_;  // exactly: the run ends there
  }
  return start_ + next_ * interval_;
}

OutputSchedule::Due OutputSchedule::after_step(double time, long cycle) {
  if (every_step_) {
    return {true, true};
  }
  Due due;
  due.frame = !finished() && time >= next_frame_time() * (1.0 - kTimeSlack);
  while (!finished() && next_frame_time() <= time * (1.0 + kTimeSlack)) {
    ++next_;
  }
  due.history = due.frame || cycle % history_interval_ == 0;
  return due;
}

double OutputSchedule::land_on_frame(double time, double dt) const {
  return finished() ? dt : std::min(dt, next_frame_time() - time);
}

}  // namespace sf
