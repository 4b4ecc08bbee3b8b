// roomba_mapper's conversions without a master (roomba_mapper.h): a LaserScan as the core's
// view, a tf transform as a planar pose (a tilted frame refused), and its parameters' names in
// the errors (gmapping's: ~delta, ~maxUrange, ~occ_thresh).
#include <gtest/gtest.h>

#include <cmath>

#include "../../src/ros/roomba_mapper.h"
#include "../../src/ros/scan_input.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"

namespace roomba_rrt::mapper_node {
namespace {

TEST(MapperRos, LaserScanIsViewedWithItsOwnRanges) {
  sensor_msgs::LaserScan scan;
  scan.angle_min = -1;
  scan.angle_max = 1;
  scan.angle_increment = 1;
  scan.range_min = 0.1f;
  scan.range_max = 4;
  scan.ranges = {1, 2, 3};
  const mapping::ScanView v = nodes::scanView(scan);
  EXPECT_EQ(v.ranges, scan.ranges.data());
  EXPECT_EQ(v.count, 3u);
  EXPECT_FLOAT_EQ(v.range_min, 0.1f);
  EXPECT_EQ(mapping::checkScan(v), "");
  scan.angle_max = 2;
  EXPECT_EQ(mapping::checkScan(nodes::scanView(scan)).rfind("angle_max:", 0), 0u);
}

TEST(MapperRos, TransformBecomesAPlanarPoseAndATiltedOneIsRefused) {
  geometry_msgs::Transform t;
  t.translation.x = 1.5;
  t.translation.y = -2;
  t.rotation.z = std::sin(0.3);  // 0.6 rad about z
  t.rotation.w = std::cos(0.3);
  robot::Pose2D pose;
  ASSERT_EQ(nodes::planarPose(t, &pose), "");
  EXPECT_DOUBLE_EQ(pose.x, 1.5);
  EXPECT_DOUBLE_EQ(pose.y, -2);
  EXPECT_NEAR(pose.theta, 0.6, 1e-12);
  t.rotation.x = std::sin(0.2);  // rolled
  t.rotation.z = 0;
  t.rotation.w = std::cos(0.2);
  EXPECT_EQ(nodes::planarPose(t, &pose).rfind("tilted by 0.4", 0), 0u);
  t.rotation.x = 0;
  t.translation.x = NAN;
  EXPECT_EQ(nodes::planarPose(t, &pose), "not finite");
}

}  // namespace
}  // namespace roomba_rrt::mapper_node
