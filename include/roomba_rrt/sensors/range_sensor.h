// Planar range sensors mounted on a robot: a 2D lidar, the Roomba's IR light bumper, any ranger
// that casts a fan of rays in the floor plane. What a world file's `sensors:` section describes
// (doc/simulation.md, "Sensors"), its two presets and its rules. ROS-free; ray_cast.h casts the
// rays, scanner.h schedules the scans of every robot in simulated time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::sensors {

/// One planar ranger. Ray k (0 ≤ k < samples) leaves the mounting point at angle_min + k ·
/// angleIncrement() from the sensor's heading, as sensor_msgs/LaserScan numbers its ranges.
struct RangeSensorSpec {
  std::string name = "scan";        ///< its topic, under the robot's namespace
  std::string frame = "base_scan";  ///< its tf frame, child of the robot's base_link
  robot::Pose2D mount;              ///< x, y (m) and yaw (rad) on the robot, in base_link
  double angle_min = 0;             ///< first ray, rad from the sensor's heading
  double angle_max = 0;             ///< last ray, rad (= angle_min for one sample)
  int samples = 1;                  ///< rays per scan
  double range_min = 0;             ///< m: a nearer return reads −inf (REP 117)
  double range_max = 1;             ///< m: no return within it reads +inf (REP 117)
  double rate = 5;                  ///< scans per simulated second
  double noise_stddev = 0;          ///< m, Gaussian noise added to every return
  std::uint32_t seed = 0;           ///< the noise's seed (the same scans for the same seed)

  /// Angle between consecutive rays (0 for one sample).
  double angleIncrement() const {
    return samples > 1 ? (angle_max - angle_min) / (samples - 1) : 0.0;
  }
};

/// The supported ranges (validate() refuses anything outside them, naming the field).
struct SensorLimits {
  static constexpr int kMaxSamples = 100000;      ///< rays per scan
  static constexpr double kMaxRange = 1000;       ///< range_max ≤ this, m
  static constexpr double kMaxNoise = 100;        ///< noise_stddev ≤ this, m
  static constexpr std::size_t kMaxSensors = 32;  ///< sensors per robot
  /// Rays of one scan of every sensor of every robot together (the scanner keeps each ray's
  /// direction and range: 20 MB at most).
  static constexpr std::size_t kMaxWorldSamples = 1000000;
};

/// An LDS-style 360° lidar as on a TurtleBot3 (its hls_lfcd_lds driver's scan): topic "scan",
/// frame "base_scan" at the robot's centre, 360 rays one degree apart starting straight ahead
/// (angle_min 0, angle_max 359°), 0.12–3.5 m, 5 Hz, no noise.
RangeSensorSpec ldsPreset();

/// The Roomba's IR light bumper: six forward beams over ±70° from the front of the bumper
/// (mounted at x = robot_radius), reaching 0.15 m beyond it (range_min 0), 20 Hz; topic
/// "ir_bumper", frame "base_ir_bumper".
RangeSensorSpec irBumperPreset(double robot_radius);

/// The preset called `name` ("lds" or "ir_bumper") for a robot of `robot_radius`. Throws
/// util::InvalidInput naming `field` for any other name.
RangeSensorSpec preset(const std::string& name, double robot_radius, const std::string& field);

/// Throws util::InvalidInput naming the bad field under `prefix` ("sensors[0].samples: must be in
/// [1, 100000], got 0"): a name or frame that is not a ROS name without slashes, no samples,
/// angles that are not finite or span more than a turn (angle_max < angle_min), range_min < 0 or
/// ≥ range_max, range_max beyond SensorLimits, a rate that is not positive or above the
/// simulator's step rate (1 / step), NaN or negative noise, a mounting pose that is not finite or
/// lies outside the robot's disc of `robot_radius`.
void validate(const RangeSensorSpec& sensor, const std::string& prefix, double robot_radius,
              double step);

/// The same for a robot's list (at most SensorLimits::kMaxSensors, each as above, under
/// `prefix`[k]), and no two with the same name or frame.
void validate(const std::vector<RangeSensorSpec>& sensors, const std::string& prefix,
              double robot_radius, double step);

}  // namespace roomba_rrt::sensors
