// Every robot's range sensors in simulated time: which scans are due at a step, and their ranges
// (ray_cast.h) with the seeded noise, as sensor_msgs/LaserScan wants them (REP 117). ROS-free;
// roomba_sim publishes what it returns.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sensors/range_sensor.h"
#include "roomba_rrt/sensors/ray_cast.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sensors {

/// One scan of one sensor.
struct Scan {
  std::size_t robot = 0;   ///< index in World::robots
  std::size_t sensor = 0;  ///< index in that robot's RobotSpec::sensors
  double time = 0;         ///< simulated time of the pose it was taken from, s
  /// Ray k's range (m) in [range_min, range_max], −inf for a return nearer than range_min, +inf
  /// for none within range_max (REP 117).
  std::vector<float> ranges;
};

/// The directions of a sensor's rays relative to its heading (cos and sin of angle_min + k ·
/// angleIncrement()), computed once: a scan then turns them by the heading.
struct RayFan {
  explicit RayFan(const RangeSensorSpec& spec);
  std::vector<double> cos, sin;
};

/// The ranges a sensor `spec` (its rays `fan`) mounted on a robot at `pose` reads, into `ranges`
/// (resized to spec.samples): the exact distance along each ray to the first wall, piece of
/// furniture, blocked map cell or disc of `others`; −inf below range_min, +inf beyond range_max; a
/// return within the range gets Gaussian noise of spec.noise_stddev from `noise`, clamped to
/// [range_min, range_max] (a noisy reading never turns into "no return").
void measure(const RayCaster& caster, const RangeSensorSpec& spec, const RayFan& fan,
             const robot::Pose2D& pose, const std::vector<geometry::Circle>& others,
             std::mt19937& noise, std::vector<float>& ranges);

/// Schedules and takes the scans of every robot's sensors (World::robots[i].sensors).
class Scanner {
 public:
  explicit Scanner(const world::World& world);

  /// The scans due at simulated `time` (s, non-decreasing between calls) with the robots at
  /// `poses` (one per robot): a sensor of rate f scans at the first call with time ≥ n / f for
  /// n = 0, 1, 2, ... (at most once per call), its rays also hitting the other robots' discs.
  /// The returned scans live until the next call.
  const std::vector<Scan>& scan(double time, const std::vector<robot::Pose2D>& poses);

  /// Whether any robot has a sensor.
  bool empty() const { return sensors_.empty(); }
  std::size_t rays() const { return rays_; }  ///< rays cast so far

 private:
  struct Sensor {
    std::size_t robot, index;
    RangeSensorSpec spec;
    RayFan fan;
    std::mt19937 noise;
    double next_time = 0;  ///< s
  };
  RayCaster caster_;
  std::vector<double> radii_;
  std::vector<Sensor> sensors_;
  std::vector<Scan> scans_;
  std::vector<geometry::Circle> others_;
  std::size_t rays_ = 0;
};

}  // namespace roomba_rrt::sensors
