// roomba_map_saver: map_server's map_saver for Debian, which ships no map_server. Waits for one
// map on `map` (remap with map:=/other), writes NAME.pgm and NAME.yaml in map_server's format
// (mapping/map_saver.h) and exits; `roomba_sim --world NAME.yaml` or any map_server reads them.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include "../ros/map_messages.h"
#include "roomba_rrt/mapping/map_saver.h"
#include "roomba_rrt/util/invalid_input.h"

namespace {

constexpr const char* kUsage =
    "Usage: rosrun roomba_rrt roomba_map_saver [-f NAME] [--occ 65] [--free 25] [map:=/topic]\n"
    "Waits for one map on `map` and writes it as map_server's map_saver does: NAME.pgm (occupied\n"
    "cells, >= --occ, black; free cells, 0 to --free, white; the rest grey) and NAME.yaml.\n"
    "NAME defaults to 'map'. Read it back with `scripts/run --world NAME.yaml` or map_server.\n";

struct Options {
  std::string name = "map";
  roomba_rrt::mapping::SaveThresholds thresholds;
};

/// The options, or exits (0 after --help, 2 with the usage for anything else it cannot read).
Options parse(const std::vector<std::string>& args) {
  Options o;
  for (std::size_t k = 1; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    const bool has_value = k + 1 < args.size();
    int* threshold = a == "--occ"    ? &o.thresholds.occupied
                     : a == "--free" ? &o.thresholds.free
                                     : nullptr;
    if (a == "-f" && has_value) {
      o.name = args[++k];
    } else if (threshold && has_value) {
      char* end = nullptr;
      const long v = std::strtol(args[++k].c_str(), &end, 10);
      if (*end != '\0' || v < 0 || v > 100) {
        std::cerr << "roomba_map_saver: " << a << ": must be an integer in [0, 100], got '"
                  << args[k] << "'\n";
        std::exit(2);
      }
      *threshold = static_cast<int>(v);
    } else {
      std::cerr << "roomba_map_saver: " << a << (has_value ? ": unknown" : ": needs a value")
                << "\n"
                << kUsage;
      std::exit(2);
    }
  }
  if (o.thresholds.free >= o.thresholds.occupied) {
    std::cerr << "roomba_map_saver: --free (" << o.thresholds.free << ") must be below --occ ("
              << o.thresholds.occupied << ")\n";
    std::exit(2);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") {
      std::cout << kUsage;
      return 0;
    }
  }
  ros::init(argc, argv, "roomba_map_saver", ros::init_options::AnonymousName);
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  const Options o = parse(args);
  ros::NodeHandle nh;
  int exit_code = 1;
  const ros::Subscriber sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& message) {
        roomba_rrt::geometry::OccupancyGrid grid;
        const std::string bad = roomba_rrt::nodes::fromMapMessage(*message, &grid);
        if (!bad.empty()) {
          ROS_ERROR("roomba_map_saver: the map on %s is not a map: %s", sub.getTopic().c_str(),
                    bad.c_str());
        } else {
          ROS_INFO("roomba_map_saver: received a %d x %d map @ %.3f m/pix", grid.width, grid.height,
                   grid.resolution);
          try {
            const std::string yaml = roomba_rrt::mapping::saveMap(grid, o.name, o.thresholds);
            ROS_INFO("roomba_map_saver: wrote %s.pgm and %s", o.name.c_str(), yaml.c_str());
            exit_code = 0;
          } catch (const roomba_rrt::util::InvalidInput& e) {
            ROS_ERROR("roomba_map_saver: %s", e.what());
          }
        }
        ros::shutdown();
      });
  ROS_INFO("roomba_map_saver: waiting for the map on %s", sub.getTopic().c_str());
  ros::spin();
  return exit_code;
}
