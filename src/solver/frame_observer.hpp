#pragma once
// The loop observer that writes frames and history rows on the output schedule (the output
// process writes; in a distributed run every process gathers the state first).
#include "solver/frame_output.hpp"
#include "solver/output_schedule.hpp"
#include "solver/time_loop.hpp"

namespace sf {

class FrameObserver final : public LoopObserver {
 public:
  /// output: null on a process that writes nothing. gather: gather the state to the output
  /// process before writing (collective: every process has the observer). land_on_frames: steps
  /// are cut to land on the frame times. last_frame_time (s) is kept up to date.
  FrameObserver(const Model& model, OutputSchedule& schedule, FrameOutput* output, bool gather,
                bool land_on_frames, double& last_frame_time)
      : model_(model),
        schedule_(schedule),
        output_(output),
        gather_(gather),
        land_on_frames_(land_on_frames),
        last_frame_time_(last_frame_time) {}

  double bound_step(const SolutionState& s, double dt) override;
  bool after_step(SolutionState& s) override;

 private:
  const Model& model_;
  OutputSchedule& schedule_;
  FrameOutput* output_;
  bool gather_;
  bool land_on_frames_;
  double& last_frame_time_;
};

}  // namespace sf
