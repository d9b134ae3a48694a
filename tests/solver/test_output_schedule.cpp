// OutputSchedule: frames at the first step at or past each frame time, one frame for several
// passed at once, the last exactly at the end, history every interval and with every frame, and
// steps shortened to land on frame times.
#include "solver/output_schedule.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sf {
namespace {

TEST(OutputSchedule, FramesAtTheFirstStepPastEachFrameTime) {
  // 4 frames over 1 s from t = 0: frame times 0.25, 0.5, 0.75, 1. Steps of 0.1 s (exact in
  // decimal, not in binary: the accumulated times carry round-off, as a run's do).
  OutputSchedule schedule(0.0, 1.0, 4, 1000);
  std::vector<int> frame_cycles;
  double t = 0.0;
  for (long cycle = 1; cycle <= 10; ++cycle) {
    t += 0.1;
    if (schedule.after_step(t, cycle).frame) {
      frame_cycles.push_back(static_cast<int>(cycle));
    }
  }
  // 0.3 >= 0.25, 0.5 (within the slack of 0.5), 0.8 >= 0.75, 1.0 (within the slack of 1).
  EXPECT_EQ(frame_cycles, (std::vector<int>{3, 5, 8, 10}));
  EXPECT_TRUE(schedule.finished());
  EXPECT_FALSE(schedule.after_step(1.1, 11).frame);  // nothing after the last frame
}

TEST(OutputSchedule, OneFrameForSeveralFrameTimesPassedInOneStep) {
  OutputSchedule schedule(0.0, 1.0, 10, 1000);
  EXPECT_TRUE(schedule.after_step(0.35, 1).frame);  // passes 0.1, 0.2 and 0.3: one frame
  EXPECT_DOUBLE_EQ(schedule.next_frame_time(), 0.4);
  EXPECT_FALSE(schedule.after_step(0.39, 2).frame);
  EXPECT_TRUE(schedule.after_step(0.4, 3).frame);
}

TEST(OutputSchedule, HistoryEveryIntervalAndWithEveryFrame) {
  OutputSchedule schedule(0.0, 1.0, 2, 3);
  EXPECT_FALSE(schedule.after_step(0.1, 1).history);
  EXPECT_TRUE(schedule.after_step(0.2, 3).history);             // cycle 3: the interval
  const OutputSchedule::Due due = schedule.after_step(0.5, 4);  // the frame at 0.5
  EXPECT_TRUE(due.frame);
  EXPECT_TRUE(due.history);
}

TEST(OutputSchedule, LandingOnFrameTimesFromAnOffsetStart) {
  // The springback's release: 3 frames over 0.3 s starting at t0 = 2; steps of 0.07 s land on
  // 2.1, 2.2 and exactly on the end 2.3.
  const double t0 = 2.0;
  OutputSchedule schedule(t0, 0.3, 3, 1000);
  std::vector<double> frame_times;
  double t = t0;
  for (long cycle = 1; cycle < 100 && !schedule.finished(); ++cycle) {
    t += schedule.land_on_frame(t, 0.07);
    if (schedule.after_step(t, cycle).frame) {
      frame_times.push_back(t);
    }
  }
  ASSERT_EQ(frame_times.size(), 3u);
  EXPECT_DOUBLE_EQ(frame_times[0], t0 + 0.1);
  EXPECT_DOUBLE_EQ(frame_times[1], t0 + 0.2);
  EXPECT_EQ(frame_times[2], t0 + 0.3);               // the end, exactly
  EXPECT_EQ(schedule.land_on_frame(t, 0.07), 0.07);  // finished: steps are not cut any more
}

TEST(OutputSchedule, EveryStepIsAFrameAndAHistoryRow) {
  OutputSchedule schedule = OutputSchedule::every_step();
  for (long cycle = 1; cycle <= 3; ++cycle) {
    const OutputSchedule::Due due = schedule.after_step(0.1 * cycle, cycle);
    EXPECT_TRUE(due.frame);
    EXPECT_TRUE(due.history);
  }
}

}  // namespace
}  // namespace sf
