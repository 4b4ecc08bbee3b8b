// Where the robot is now, not where it was seen: over ROS the pose a tick reads is a message
// from an earlier step, and the command it computes reaches the robot later still. Drive the
// pose seen forward along the commands sent since, and the follower, its guard and the cleaning
// act on the robot's present pose again.
#pragma once

#include <deque>

#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::navigation {

/// Latency compensation for a unicycle (a Smith predictor without a model error term): the robot
/// seen at `pose` has since driven the last `latency_ticks` commands, each for one tick, along
/// the exact arcs of the simulator's model (robot::integrateArc). With no latency it returns the
/// pose seen. The commands are the ones the caller sent, so a robot stopped by a wall or by a
/// lost command is predicted a few millimetres ahead at most (ticks × speed).
class PosePredictor {
 public:
  static constexpr double kMaxLatency = 1.0;  ///< s

  /// util::InvalidInput naming "pose_latency" unless 0 ≤ latency ≤ kMaxLatency, or "rate" unless
  /// > 0. The latency is rounded to whole ticks of 1 / rate.
  PosePredictor(double latency, double rate);

  /// The pose `seen` driven forward along the commands of the last latency_ticks() ticks.
  robot::Pose2D predict(const robot::Pose2D& seen) const;
  /// The command sent this tick (the oldest one drops out).
  void sent(const robot::Velocity& cmd);

  int latency_ticks() const { return ticks_; }

 private:
  int ticks_;
  double dt_;
  std::deque<robot::Velocity> sent_;  ///< oldest first, at most ticks_
};

}  // namespace roomba_rrt::navigation
