// roomba_sim + roomba_mapper through a real master (mapper.test): what a gmapping user checks.
// The map arrives latched on /map in frame map and again at ~map_update_interval, agrees with the
// furnished room where the LDS saw it (walls where the world has them), /map_metadata and
// ~dynamic_map give the same; roomba_map_saver writes it so that a world file reads it back;
// scans without a pose or whose angles do not add up are warned about; a bad parameter stops the
// node naming it.
#include <gtest/gtest.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/LaserScan.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../../src/ros/map_messages.h"
#include "../common/run_node.h"
#include "../common/wait_until.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/mapping/map_accuracy.h"
#include "roomba_rrt/world/world_file.h"

namespace {

using roomba_rrt::geometry::OccupancyGrid;
using roomba_rrt::test::waitUntil;

TEST(Mapper, map_is_published_latched_with_the_walls_where_the_world_has_them) {
  ros::NodeHandle nh;
  std::vector<nav_msgs::OccupancyGrid> maps;
  std::vector<nav_msgs::MapMetaData> metadata;
  ros::Subscriber sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 10, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { maps.push_back(*m); });
  ros::Subscriber meta_sub = nh.subscribe<nav_msgs::MapMetaData>(
      "/map_metadata", 10,
      [&](const nav_msgs::MapMetaData::ConstPtr& m) { metadata.push_back(*m); });
  // A subscriber that connects while the first map goes out may get it twice (latched and
  // published): a refresh is a later stamp.
  ASSERT_TRUE(waitUntil(
      [&] {
        return !maps.empty() && maps.back().header.stamp > maps.front().header.stamp &&
               !metadata.empty();
      },
      60.0))
      << maps.size() << " maps";
  EXPECT_TRUE(sub.getNumPublishers() == 1);
  const nav_msgs::OccupancyGrid& map = maps.back();
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(metadata.back().width, map.info.width);

  OccupancyGrid grid;
  ASSERT_EQ(roomba_rrt::nodes::fromMapMessage(map, &grid), "");
  const roomba_rrt::world::World world =
      roomba_rrt::world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  const roomba_rrt::mapping::MapAccuracy a = roomba_rrt::mapping::compare(grid, world);
  EXPECT_GT(a.known, 2000u);
  EXPECT_GE(a.agreement(), 0.99) << a.agreeing << " of " << a.known;
  EXPECT_EQ(a.walls_off, 0u);
  // From (3.2, 2.4): the right wall 3.2 m ahead (x = 6.4) is there, the floor before it free.
  EXPECT_EQ(grid.at(grid.column(6.42), grid.row(2.41)), OccupancyGrid::kOccupied);
  EXPECT_EQ(grid.at(grid.column(6.3), grid.row(2.41)), OccupancyGrid::kFree);
  EXPECT_EQ(grid.at(grid.column(3.2), grid.row(2.4)), OccupancyGrid::kFree);

  // ~dynamic_map: the map as it is now.
  nav_msgs::GetMap get;
  ASSERT_TRUE(ros::service::waitForService("/roomba_mapper/dynamic_map", 10000));
  ASSERT_TRUE(ros::service::call("/roomba_mapper/dynamic_map", get));
  EXPECT_EQ(get.response.map.info.width, map.info.width);
  EXPECT_EQ(get.response.map.header.frame_id, "map");

  // roomba_map_saver writes it; the world file reader (roomba_sim --world) reads it back.
  const std::string dir = std::filesystem::temp_directory_path() / "mapper_rostest";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const roomba_rrt::test::Outcome saved = roomba_rrt::test::runCommand(
      "timeout 30 " + roomba_rrt::test::siblingExecutable("roomba_map_saver") + " -f " + dir +
      "/built");
  ASSERT_EQ(saved.exit_code, 0) << saved.output;
  const roomba_rrt::world::WorldFile file = roomba_rrt::world::readWorldFile(dir + "/built.yaml");
  ASSERT_TRUE(file.world.room.map);
  const OccupancyGrid& back = *file.world.room.map;
  EXPECT_EQ(back.width, grid.width);
  EXPECT_EQ(back.origin.x, grid.origin.x);
  std::size_t occupied = 0;
  for (std::size_t k = 0; k < back.cells.size(); ++k) occupied += back.cells[k] == 100;
  EXPECT_GE(occupied, a.occupied);  // the map may have grown between the two
  std::filesystem::remove_all(dir);
}

TEST(Mapper, scans_it_cannot_use_are_skipped_with_a_warning_saying_why) {
  ros::NodeHandle nh;
  std::vector<std::string> warnings;
  ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& log) {
        if (log->name == "/roomba_mapper" && log->level == rosgraph_msgs::Log::WARN) {
          warnings.push_back(log->msg);
        }
      });
  ros::Publisher scans = nh.advertise<sensor_msgs::LaserScan>("/scan", 10);
  ASSERT_TRUE(waitUntil([&] { return scans.getNumSubscribers() > 0; }, 10.0));
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "nowhere";  // no tf: its pose cannot be known
  scan.angle_increment = 0.1f;
  scan.angle_max = 0.9f;
  scan.range_min = 0.1f;
  scan.range_max = 3.5f;
  scan.ranges.assign(10, 1.0f);
  // Sends the scan until the mapper's warning containing `text` is heard: each warning is
  // throttled (one per 5 s of ROS time).
  const auto sentUntilWarned = [&](const std::string& text) {
    return waitUntil(
        [&] {
          scan.header.stamp = ros::Time::now();
          scans.publish(scan);
          for (const std::string& w : warnings) {
            if (w.find(text) != std::string::npos) return true;
          }
          return false;
        },
        20.0);
  };
  EXPECT_TRUE(sentUntilWarned("no pose of nowhere in odom"));
  scan.header.frame_id = "base_scan";
  scan.angle_max = 2.0f;  // 10 rays of 0.1 rad cannot end at 2 rad
  EXPECT_TRUE(sentUntilWarned("scan skipped: angle_max: 2 is not angle_min + (10 - 1)"));
}

TEST(Mapper, bad_parameter_stops_the_node_naming_it) {
  const roomba_rrt::test::Outcome bad =
      roomba_rrt::test::runNode("roomba_mapper", "bad_mapper", "_delta:=0");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("~delta: must be in [0.001, 10] m, got 0"), std::string::npos)
      << bad.output;
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "mapper_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
