// roomba_sim in a map world through a real master (sim_map.test): /map and /map_metadata are
// latched, in frame map, and equal the map file cell by cell (read here with the same reader
// map_server's users would compare against: geometry::loadMap); roomba_fsm drives the robot
// through the apartment for 60 s of robot time and no /odom puts its disc on a blocked cell.
#include <gtest/gtest.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <functional>
#include <string>
#include <vector>

#include "../common/wait_until.h"
#include "roomba_rrt/geometry/map_file.h"

namespace {

using roomba_rrt::geometry::OccupancyGrid;

using roomba_rrt::test::waitUntil;

TEST(SimMap, map_is_the_file_cell_by_cell_and_the_robot_never_ends_on_a_wall) {
  const roomba_rrt::geometry::MapFile file =
      roomba_rrt::geometry::loadMap(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml");
  ros::NodeHandle nh;
  nav_msgs::OccupancyGrid map;
  nav_msgs::MapMetaData metadata;
  bool have_map = false, have_metadata = false;
  auto map_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) {
        map = *m;
        have_map = true;
      });
  auto metadata_sub = nh.subscribe<nav_msgs::MapMetaData>(
      "/map_metadata", 1, [&](const nav_msgs::MapMetaData::ConstPtr& m) {
        metadata = *m;
        have_metadata = true;
      });
  ASSERT_TRUE(waitUntil([&] { return have_map && have_metadata; }, 30)) << "no latched /map";
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.info.width, static_cast<unsigned>(file.grid.width));
  EXPECT_EQ(map.info.height, static_cast<unsigned>(file.grid.height));
  EXPECT_FLOAT_EQ(map.info.resolution, static_cast<float>(file.resolution));
  EXPECT_DOUBLE_EQ(map.info.origin.position.x, file.origin.x);
  EXPECT_DOUBLE_EQ(map.info.origin.position.y, file.origin.y);
  EXPECT_EQ(std::vector<std::int8_t>(map.data.begin(), map.data.end()), file.grid.cells);
  EXPECT_EQ(metadata, map.info);

  // The robot's disc (0.17 m) never ends a step on a blocked cell: its centre keeps the radius
  // from every blocked square (up to the simulator's contact tolerance).
  long odoms = 0, on_walls = 0;
  double first_stamp = -1, last_stamp = 0;
  auto odom_sub =
      nh.subscribe<nav_msgs::Odometry>("/odom", 100, [&](const nav_msgs::Odometry::ConstPtr& odom) {
        const auto& p = odom->pose.pose.position;
        ++odoms;
        if (first_stamp < 0) first_stamp = odom->header.stamp.toSec();
        last_stamp = odom->header.stamp.toSec();
        if (roomba_rrt::geometry::distanceToBlocked(file.grid, {p.x, p.y}, 1.0) < 0.17 - 1e-6) {
          ++on_walls;
        }
      });
  ASSERT_TRUE(waitUntil([&] { return first_stamp >= 0 && last_stamp - first_stamp > 60; }, 60))
      << odoms << " /odom in " << last_stamp - first_stamp << " s of robot time";
  EXPECT_EQ(on_walls, 0) << "of " << odoms << " /odom";
}

/// sim_map_hidden.test: roomba_sim with ~publish_map false beside roomba_mapper. The map on /map
/// is the mapper's alone: roomba_sim does not publish it, and what arrives is not the file.
TEST(SimMapHidden, the_true_map_stays_the_simulators_and_map_is_the_mappers) {
  const roomba_rrt::geometry::MapFile file =
      roomba_rrt::geometry::loadMap(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml");
  ros::NodeHandle nh;
  nav_msgs::OccupancyGrid map;
  bool have_map = false;
  auto map_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) {
        map = *m;
        have_map = true;
      });
  ASSERT_TRUE(waitUntil([&] { return have_map; }, 30)) << "the mapper published no /map";
  // Who publishes /map, from the master.
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  ASSERT_TRUE(ros::master::execute("getSystemState", request, response, payload, true));
  std::vector<std::string> publishers;
  for (int t = 0; t < payload[0].size(); ++t) {
    if (static_cast<std::string>(payload[0][t][0]) != "/map") continue;
    for (int n = 0; n < payload[0][t][1].size(); ++n) publishers.push_back(payload[0][t][1][n]);
  }
  EXPECT_EQ(publishers, std::vector<std::string>{"/roomba_mapper"});
  long unknown = 0;
  for (const std::int8_t cell : map.data) unknown += cell == OccupancyGrid::kUnknown;
  EXPECT_GT(unknown, 0) << "a map with nothing unknown: the file's, not one the robot builds";
  EXPECT_NE(map.info.width * map.info.height,
            static_cast<unsigned>(file.grid.width * file.grid.height));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_map_test");
  return RUN_ALL_TESTS();
}
