// How late the robot's commands land, and how fast the cleaning may drive under it. Over ROS on a
// busy machine (roomba_sim at 20x real time beside other work) roomba_bt's ticks fall behind the
// simulator: a command holds for several steps, computed from a pose several steps old, so the
// robot overshoots the rows' ends and bumps. The node feeds the times; the estimate and the speed
// policy live here, ROS-free.
#pragma once

namespace roomba_rrt::navigation {

/// The latency of the control loop from the times of its ticks, in the robot's clock (over ROS
/// the simulator's time): each tick gives the time it runs and the stamp of the pose it acts on.
/// A sample is the pose's age plus the time since the previous tick's time (how long the last
/// command held; ticks at one time, a node catching up, share the gap of the first). The
/// estimate follows a rising sample at once and falls back over kReleaseTime, so that a loop
/// late now and then counts as late until it has been on time for a while.
class CommandLatency {
 public:
  /// s of robot time for the estimate to fall by 1/e: from kMaxSample to on time in 4 s.
  static constexpr double kReleaseTime = 2.0;
  /// s: longer samples count as this. A pause (roomba_bt stands still while the bumper is
  /// silent) is no longer a command held: at 0.5 s (30 ticks at 60 Hz) the speeds are at their
  /// least already (LatencySpeedPolicy::kMinScale).
  static constexpr double kMaxSample = 0.5;

  /// util::InvalidInput naming "rate" unless > 0.
  explicit CommandLatency(double rate);

  /// A tick at `now` acting on a pose stamped `pose_stamp` (s). Non-finite times, or a clock that
  /// went back (a simulator reset), start afresh.
  void observe(double now, double pose_stamp);
  /// The estimate (s): one tick before the first observation.
  double latency() const { return latency_; }
  /// The estimate in ticks of the rate.
  double ticks() const { return latency_ * rate_; }

 private:
  double rate_;
  double latency_;
  double last_now_ = 0, gap_ = 0;
  bool started_ = false;
};

/// How fast the cleaning drives under a latency: at full speed while the loop is on time (up to
/// kOnTimeTicks: in-process a command computed from a step's pose drives the next step, over ROS
/// one or two steps later; roomba_coverage --lag 3 is 4), slower in proportion beyond, so that the
/// distance driven before a late command lands stays what it is on time; never below kMinScale.
struct LatencySpeedPolicy {
  static constexpr double kOnTimeTicks = 4;
  /// Ticks beyond kOnTimeTicks still on time: times that are whole steps apart differ from them
  /// by rounding (roomba_coverage --lag 3 measures 4.000000001 ticks).
  static constexpr double kSlackTicks = 0.5;
  static constexpr double kMinScale = 0.2;
  /// The factor (kMinScale..1) on the cleaning's linear and angular speeds at `latency_ticks`.
  static double scale(double latency_ticks);
};

}  // namespace roomba_rrt::navigation
