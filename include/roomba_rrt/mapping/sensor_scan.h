// What an in-process user (a tool, the benchmark, a cleaning run) hands the mapper for a scan of
// the simulator's sensors (sensors/scanner.h): the scan as a ScanView and the sensor's pose in
// the map. roomba_mapper gets the same from sensor_msgs/LaserScan and tf.
#pragma once

#include <cmath>
#include <vector>

#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sensors/range_sensor.h"

namespace roomba_rrt::mapping {

/// The scan of `spec` reading `ranges` (one per sample), as its LaserScan would carry it.
inline ScanView scanView(const sensors::RangeSensorSpec& spec, const std::vector<float>& ranges) {
  return {spec.angle_min, spec.angle_max, spec.angleIncrement(), spec.range_min,
          spec.range_max, ranges.data(),  ranges.size()};
}

/// The pose of a sensor mounted at `mount` (in base_link) on a robot at `robot` (in the map).
inline robot::Pose2D mountedPose(const robot::Pose2D& robot, const robot::Pose2D& mount) {
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  return {robot.x + c * mount.x - s * mount.y, robot.y + s * mount.x + c * mount.y,
          robot.theta + mount.theta};
}

}  // namespace roomba_rrt::mapping
