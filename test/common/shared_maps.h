// The real maps some tests read: occupancy maps of public ROS projects, kept beside the
// repository (ROOMBA_RRT_SHARED_MAPS, `../shared/maps`), never copied into the package. In a
// user's catkin workspace they are absent: such a test skips, saying which map it wanted and where
// to get it; in CI (the environment variable CI is `true`) a missing map fails the test instead.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace roomba_rrt::test {

/// Where a shared map comes from (its public repository and path), for the skip message.
inline std::string sharedMapSource(const std::string& name) {
  if (name == "turtlebot3_world")
    return "ROBOTIS-GIT/turtlebot3, turtlebot3_navigation2/map/map.yaml";
  if (name == "depot") return "ros-navigation/navigation2, nav2_bringup/maps/depot.yaml";
  if (name == "warehouse") return "ros-navigation/navigation2, nav2_bringup/maps/warehouse.yaml";
  if (name == "nav2_bench_100by100_15") {
    return "ros-navigation/navigation2, tools/planner_benchmarking/100by100_15.yaml";
  }
  if (name == "willow_full") return "ros-simulation/stage_ros, world/willow-full.pgm (0.1 m/pixel)";
  return "doc/testing.md#the-shared-maps";
}

/// The path of the shared map `name` (NAME.yaml in ROOMBA_RRT_SHARED_MAPS).
inline std::string sharedMapPath(const std::string& name) {
  return std::string(ROOMBA_RRT_SHARED_MAPS) + "/" + name + ".yaml";
}

/// Empty when the map is there, else what is missing and where to get it.
inline std::string missingSharedMap(const std::string& name) {
  const std::string path = sharedMapPath(name);
  if (std::filesystem::exists(path)) return "";
  return "needs the map " + path + " (from " + sharedMapSource(name) +
         "; see doc/testing.md#the-shared-maps)";
}

/// True in CI, where the maps must be there.
inline bool sharedMapsRequired() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace roomba_rrt::test

/// In a test body: skips the test (fails it in CI) when the shared map `name` is absent.
#define ROOMBA_RRT_REQUIRE_SHARED_MAP(name)                                            \
  if (const std::string missing_ = ::roomba_rrt::test::missingSharedMap(name);         \
      !missing_.empty()) {                                                             \
    if (::roomba_rrt::test::sharedMapsRequired()) GTEST_FAIL() << missing_ << " (CI)"; \
    GTEST_SKIP() << missing_;                                                          \
  }
