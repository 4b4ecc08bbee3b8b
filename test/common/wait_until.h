// Waiting in a rostest's test node: spin the callbacks until a condition holds, with a bound in
// wall time (the simulator may run faster than the wall clock, or not at all).
#pragma once

#include <ros/ros.h>

#include <functional>

namespace roomba_rrt::test {

/// Spins until `done` holds (true) or `wall_seconds` of wall time pass (false).
inline bool waitUntil(const std::function<bool()>& done, double wall_seconds) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(wall_seconds);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    if (done()) return true;
    ros::WallDuration(0.002).sleep();
  }
  return false;
}

}  // namespace roomba_rrt::test
