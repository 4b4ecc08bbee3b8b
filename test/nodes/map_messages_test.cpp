// Maps to and from nav_msgs/OccupancyGrid: what roomba_sim publishes is map_server's message,
// cell by cell, and what rrt_planner takes from /map is either a grid or a reason naming a field.
#include "../../src/ros/map_messages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace roomba_rrt::nodes {
namespace {

geometry::OccupancyGrid smallGrid() {
  geometry::OccupancyGrid grid;
  grid.width = 3;
  grid.height = 2;
  grid.resolution = 0.05;
  grid.origin = {-10.0, -7.5};
  grid.cells = {0, 100, -1, 100, 0, 0};
  return grid;
}

TEST(MapMessages, the_map_goes_out_as_map_server_publishes_it_cell_by_cell) {
  const geometry::OccupancyGrid grid = smallGrid();
  const ros::Time stamp(12, 5);
  const nav_msgs::OccupancyGrid map = toMapMessage(grid, stamp);
  EXPECT_EQ(map.header.frame_id, "map");
  EXPECT_EQ(map.header.stamp, stamp);
  EXPECT_EQ(map.info.width, 3u);
  EXPECT_EQ(map.info.height, 2u);
  EXPECT_FLOAT_EQ(map.info.resolution, 0.05f);
  EXPECT_EQ(map.info.origin.position.x, -10.0);
  EXPECT_EQ(map.info.origin.position.y, -7.5);
  EXPECT_EQ(map.info.origin.orientation.w, 1.0);
  EXPECT_EQ(std::vector<std::int8_t>(map.data.begin(), map.data.end()), grid.cells);
  EXPECT_EQ(toMapMetaData(grid, stamp), map.info);
}

TEST(MapMessages, a_received_map_is_the_same_grid) {
  const geometry::OccupancyGrid sent = smallGrid();
  geometry::OccupancyGrid received;
  ASSERT_EQ(fromMapMessage(toMapMessage(sent, ros::Time(1)), &received), "");
  EXPECT_EQ(received.width, 3);
  EXPECT_EQ(received.height, 2);
  EXPECT_NEAR(received.resolution, 0.05, 1e-8);  // the message's float32
  EXPECT_EQ(received.origin.x, -10.0);
  EXPECT_EQ(received.cells, sent.cells);
}

TEST(MapMessages, a_map_that_cannot_be_one_is_refused_naming_the_field) {
  geometry::OccupancyGrid untouched;
  auto refusal = [&](auto change) {
    nav_msgs::OccupancyGrid m = toMapMessage(smallGrid(), ros::Time(1));
    change(m);
    return fromMapMessage(m, &untouched);
  };
  EXPECT_EQ(refusal([](auto& m) { m.info.resolution = 0; }).rfind("info.resolution:", 0), 0u);
  EXPECT_EQ(refusal([](auto& m) { m.info.resolution = NAN; }).rfind("info.resolution:", 0), 0u);
  EXPECT_EQ(refusal([](auto& m) {
              m.info.origin.position.x = INFINITY;
            }).rfind("info.origin.position.x:", 0),
            0u);
  EXPECT_EQ(refusal([](auto& m) { m.data.pop_back(); }), "data: 5 cells for 3 x 2");
  EXPECT_EQ(refusal([](auto& m) { m.info.width = 0; }).rfind("info.width, info.height:", 0), 0u);
  EXPECT_EQ(refusal([](auto& m) {
              m.info.width = 100000;
              m.info.height = 100000;  // 10^10 cells, and data does not say otherwise
            }).rfind("info.width, info.height:", 0),
            0u);
  // Found by map_message_fuzzer: the product of two such sizes overflowed a signed 64-bit count.
  EXPECT_EQ(refusal([](auto& m) {
              m.info.width = 4000000000u;
              m.info.height = 4000000000u;
            }),
            "info.width, info.height: 4000000000 x 4000000000 cells; must be 1 to 100000000 "
            "cells");
  EXPECT_EQ(refusal([](auto& m) {
              m.info.origin.orientation.z = std::sin(0.15);
              m.info.origin.orientation.w = std::cos(0.15);
            }).rfind("info.origin.orientation: a rotated map", 0),
            0u);
  EXPECT_TRUE(untouched.cells.empty());  // nothing was written
  // Issue 44, item 3: the ranges a map file is held to (map_file.h). These resolutions once
  // replaced the good map, after which every plan failed.
  for (const float resolution : {1e-30f, 1.4e-45f, 3e38f, 5e-5f, 101.0f, INFINITY}) {
    EXPECT_EQ(refusal([&](auto& m) {
                m.info.resolution = resolution;
              }).rfind("info.resolution: must be in [0.0001, 100] m, got ", 0),
              0u)
        << resolution;
  }
  EXPECT_EQ(
      refusal([](auto& m) { m.info.resolution = 1e-30f; }),
      "info.resolution: must be in [0.0001, 100] m, got 1.0000000031710769e-30");  // the float
  EXPECT_EQ(refusal([](auto& m) { m.info.origin.position.y = -2e6; }),
            "info.origin.position.y: must be in [-1e+06, 1e+06] m, got -2e+06");
  // Roll or pitch is a rotation too: such a map is refused, not read as an unrotated one.
  EXPECT_EQ(refusal([](auto& m) {
              m.info.origin.orientation.x = std::sin(0.25);
              m.info.origin.orientation.w = std::cos(0.25);
            }),
            "info.origin.orientation: a rotated map (by 0.5 rad) is not supported; rotate the "
            "image and use yaw 0");
  EXPECT_EQ(refusal([](auto& m) {
              m.info.origin.orientation.y = 0.1;
            }).rfind("info.origin.orientation: a rotated map", 0),
            0u);
  EXPECT_EQ(refusal([](auto& m) {
              m.info.origin.orientation.w = NAN;
            }).rfind("info.origin.orientation: a rotated map", 0),
            0u);
  EXPECT_TRUE(untouched.cells.empty());
  // The limits themselves are maps.
  EXPECT_EQ(refusal([](auto& m) { m.info.resolution = 100.0f; }), "");
  EXPECT_EQ(refusal([](auto& m) { m.info.origin.orientation.w = -1; }), "");
  // An unset orientation (all zero, as some publishers leave it) is no rotation.
  EXPECT_EQ(refusal([](auto& m) { m.info.origin.orientation.w = 0; }), "");
}

}  // namespace
}  // namespace roomba_rrt::nodes
