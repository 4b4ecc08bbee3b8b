// How late the commands land, from the times of the ticks, and how fast the cleaning drives under
// it: on time (in-process, over ROS at one or two steps) nothing changes; late, it slows down.
#include <gtest/gtest.h>

#include <cmath>

#include "roomba_rrt/navigation/command_latency.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::navigation {
namespace {

constexpr double kRate = 60, kDt = 1 / kRate;

/// `ticks` ticks, one a step, each acting on a pose `lag` steps old, from step `first` on.
void tickLate(CommandLatency& latency, long first, long ticks, int lag) {
  for (long k = first; k < first + ticks; ++k) latency.observe(k * kDt, (k - lag) * kDt);
}

TEST(CommandLatency, a_tick_a_step_on_a_fresh_pose_is_one_tick) {
  CommandLatency latency(kRate);
  EXPECT_DOUBLE_EQ(latency.ticks(), 1);
  tickLate(latency, 0, 600, 0);
  EXPECT_NEAR(latency.ticks(), 1, 1e-9);
  EXPECT_EQ(LatencySpeedPolicy::scale(latency.ticks()), 1);
}

TEST(CommandLatency, over_ros_and_at_roomba_coverage_lag_3_the_loop_is_on_time) {
  for (int lag : {1, 2, 3}) {
    CommandLatency latency(kRate);
    tickLate(latency, 0, 600, lag);
    EXPECT_NEAR(latency.ticks(), lag + 1, 1e-9) << "lag " << lag;
    EXPECT_EQ(LatencySpeedPolicy::scale(latency.ticks()), 1) << "lag " << lag;
  }
}

TEST(CommandLatency, an_old_pose_is_late_at_once) {
  CommandLatency latency(kRate);
  tickLate(latency, 0, 60, 0);
  latency.observe(1.0, 1.0 - 12 * kDt);  // a pose 12 steps old
  EXPECT_NEAR(latency.ticks(), 13, 1e-6);
  EXPECT_NEAR(LatencySpeedPolicy::scale(latency.ticks()), 4.0 / 13, 1e-6);
}

TEST(CommandLatency, ticks_that_fall_behind_count_the_time_the_last_command_held) {
  // A node that ticks every 10 steps, catching up with 10 ticks at one time (roomba_bt's timer
  // under load): each command held for 10 steps, though every pose is fresh.
  CommandLatency latency(kRate);
  for (long event = 1; event <= 60; ++event) {
    const double now = event * 10 * kDt;
    for (int catch_up = 0; catch_up < 10; ++catch_up) latency.observe(now, now);
  }
  EXPECT_NEAR(latency.ticks(), 10, 1e-6);
  EXPECT_NEAR(LatencySpeedPolicy::scale(latency.ticks()), 0.4, 1e-6);
}

TEST(CommandLatency, late_now_and_then_it_stays_late_then_falls_back_once_on_time) {
  CommandLatency latency(kRate);
  tickLate(latency, 0, 60, 0);
  latency.observe(79 * kDt, 79 * kDt);  // one gap of 20 steps after step 59
  EXPECT_NEAR(latency.ticks(), 20, 1e-6);
  tickLate(latency, 80, 60, 0);  // a second on time: still counted late
  EXPECT_GT(latency.ticks(), 10);
  tickLate(latency, 140, 60 * 30, 0);  // half a minute on time: back to one tick
  EXPECT_NEAR(latency.ticks(), 1, 1e-6);
  EXPECT_EQ(LatencySpeedPolicy::scale(latency.ticks()), 1);
}

TEST(CommandLatency, a_pause_counts_as_max_sample_and_a_clock_going_back_starts_afresh) {
  CommandLatency latency(kRate);
  latency.observe(0, 0);
  latency.observe(100, 100);  // paused for 100 s
  EXPECT_DOUBLE_EQ(latency.latency(), CommandLatency::kMaxSample);
  latency.observe(1, 1);  // the simulator was reset
  EXPECT_DOUBLE_EQ(latency.ticks(), 1);
  latency.observe(std::nan(""), 0);
  EXPECT_DOUBLE_EQ(latency.ticks(), 1);
  EXPECT_THROW(CommandLatency(0), util::InvalidInput);
}

TEST(LatencySpeedPolicy, slows_in_proportion_beyond_on_time_never_below_the_floor) {
  EXPECT_EQ(LatencySpeedPolicy::scale(LatencySpeedPolicy::kOnTimeTicks), 1);
  EXPECT_DOUBLE_EQ(LatencySpeedPolicy::scale(8), 0.5);
  EXPECT_DOUBLE_EQ(LatencySpeedPolicy::scale(1000), LatencySpeedPolicy::kMinScale);
  EXPECT_EQ(LatencySpeedPolicy::scale(std::nan("")), 1);
}

}  // namespace
}  // namespace roomba_rrt::navigation
