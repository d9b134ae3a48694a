#pragma once
// When a driver writes frames and history rows: one schedule for the explicit forming run, the
// static analysis, and both springback methods.
namespace sf {

/// Frames at the times start + k duration / frames, k = 1..frames (the last one exactly at
/// end = start + duration), each written at the first step (or converged increment) that ends at or
/// past it; a driver that must land on the frame times shortens its step with land_on_frame. A
/// history row is due every history_interval cycles and with every frame. Times in s.
class OutputSchedule {
 public:
  /// frames >= 1, history_interval >= 1 (cycles).
  OutputSchedule(double start, double duration, int frames, int history_interval);
  /// Every step is a frame and a history row (the implicit springback's increments).
  static OutputSchedule every_step();

  /// What is due after a step that ended at `time` (s), `cycle`.
  struct Due {
    bool frame = false;
    bool history = false;
  };
  /// Marks the frame times up to `time` as done (a step longer than the frame interval passes
  /// several: one frame is written for them).
  Due after_step(double time, long cycle);

  /// dt (s) shortened so that a step from `time` ends on the next frame time, not past it.
  double land_on_frame(double time, double dt) const;
  /// Every frame time has been passed.
  bool finished() const { return next_ > frames_; }
  /// The time of the next frame (s); the end time once finished.
  double next_frame_time() const;

 private:
  OutputSchedule() = default;
  double start_ = 0.0;
  double interval_ = 0.0;
  double end_ = 0.0;
  int frames_ = 0;
  int history_interval_ = 1;
  int next_ = 1;  // index k of the next frame time
  bool every_step_ = false;
};

}  // namespace sf
