// coverage_planner's ROS interface (coverage_ros.h), without a master: what a client of
// ~plan_coverage gets back for good requests (a path a disc can drive, rows marked, areas) and
// for bad ones (success false, the field named). The node around it: test/coverage/
// plan_coverage.test.
#include "../../src/ros/coverage_ros.h"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::coverage_node {
namespace {

CoverageDefaults furnished() {
  CoverageDefaults d;
  d.room = std::make_shared<const world::World>(world::loadWorld(
      ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml", world::PoseSource::kElsewhere));
  return d;
}

PlanCoverage::Request from(double x, double y) {
  PlanCoverage::Request r;
  r.start.x = x;
  r.start.y = y;
  return r;
}

// Every pose and every point between two poses (each 1 cm) keeps `radius` from everything.
void expectDrivable(const world::World& w, const nav_msgs::Path& path, double radius) {
  for (std::size_t k = 0; k + 1 < path.poses.size(); ++k) {
    const auto& a = path.poses[k].pose.position;
    const auto& b = path.poses[k + 1].pose.position;
    const int n = std::max(1, static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.01));
    for (int i = 0; i <= n; ++i) {
      const double x = a.x + (b.x - a.x) * i / n, y = a.y + (b.y - a.y) * i / n;
      ASSERT_FALSE(world::penetrates(w, radius, x, y)) << "pose " << k << " at " << x << ", " << y;
    }
  }
}

// The service's contract for rows: each row_starts[i] names a pose whose next pose ends that row
// (in order, one segment each), and those segments add up to row_length; every other segment is
// a transit, adding up to length - row_length.
void expectRowsAsAnswered(const PlanCoverage::Response& r) {
  std::vector<bool> row(r.path.poses.size(), false);
  for (std::size_t i = 0; i < r.row_starts.size(); ++i) {
    if (i > 0) {
      ASSERT_GT(r.row_starts[i], r.row_starts[i - 1]);
    }
    ASSERT_LT(r.row_starts[i] + 1, r.path.poses.size());
    row[r.row_starts[i]] = true;
  }
  double rows = 0, transits = 0;
  for (std::size_t k = 0; k + 1 < r.path.poses.size(); ++k) {
    const auto& a = r.path.poses[k].pose.position;
    const auto& b = r.path.poses[k + 1].pose.position;
    (row[k] ? rows : transits) += std::hypot(b.x - a.x, b.y - a.y);
  }
  EXPECT_NEAR(rows, r.row_length, 1e-6);
  EXPECT_NEAR(transits, r.length - r.row_length, 1e-6);
}

TEST(CoverageRos, the_furnished_room_is_covered_by_rows_a_disc_can_drive) {
  const CoverageDefaults d = furnished();
  const PlanCoverage::Response r = planCoverage(from(1.0, 1.0), d, ros::Time(5));
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.message, "");
  EXPECT_EQ(r.path.header.frame_id, "map");
  EXPECT_EQ(r.path.header.stamp, ros::Time(5));
  ASSERT_GT(r.path.poses.size(), 40u);
  EXPECT_DOUBLE_EQ(r.path.poses.front().pose.position.x, 1.0);  // from where the robot is
  EXPECT_DOUBLE_EQ(r.path.poses.front().pose.position.y, 1.0);
  expectDrivable(*d.room, r.path, d.room->robot().radius + d.clearance - 1e-6);
  // The floor is the room less its furniture; the reachable part is most of it, and the rows
  // sweep most of that (the touch-up of roomba_bt's tree does the rest).
  EXPECT_NEAR(r.floor_area, 6.4 * 4.8 - 1.6 * 0.6 - 0.8 * 1.5 - 1.2 * 0.4 - M_PI * 0.13, 0.1);
  EXPECT_NEAR(r.reachable_area + r.unreachable_area, r.floor_area, 1e-9);
  EXPECT_GT(r.reachable_area, 0.97 * r.floor_area);
  EXPECT_GT(r.swept_area, 0.9 * r.reachable_area);
  EXPECT_GE(r.cells, 1);
  EXPECT_GT(r.row_length, 0.8 * r.length);
  EXPECT_LE(r.row_length, r.length);
  EXPECT_GE(r.planning_time, 0);
  // The path's length is the plan's, the rows marked at their starts in order.
  double length = 0;
  for (std::size_t k = 0; k + 1 < r.path.poses.size(); ++k) {
    const auto& a = r.path.poses[k].pose.position;
    const auto& b = r.path.poses[k + 1].pose.position;
    length += std::hypot(b.x - a.x, b.y - a.y);
  }
  EXPECT_NEAR(length, r.length, 1e-6);
  ASSERT_GT(r.row_starts.size(), 10u);
  for (std::size_t i = 0; i < r.row_starts.size(); ++i) {
    const auto& a = r.path.poses[r.row_starts[i]].pose.position;
    const auto& b = r.path.poses[r.row_starts[i] + 1].pose.position;
    EXPECT_NEAR(a.y, b.y, 1e-9) << "row " << i << " runs along x";
  }
  expectRowsAsAnswered(r);
}

// Issue 44, item 2: a row of no length (both ends one point) was marked at the point before it,
// so the transit that followed was answered as a row (7.853 m of rows for row_length 6.968).
TEST(CoverageRos, a_row_of_no_length_marks_no_transit_as_a_row) {
  PlanCoverage::Request request = from(3.2, 2.4);
  request.robot_radius = 1.0;
  request.swath = 0.34;
  const PlanCoverage::Response r = planCoverage(request, furnished(), ros::Time(1));
  ASSERT_TRUE(r.success) << r.message;
  expectRowsAsAnswered(r);

  coverage::CoveragePlan plan;
  using Kind = coverage::Leg::Kind;
  plan.legs = {{Kind::kRow, {{0, 0}, {1, 0}}},
               {Kind::kTransit, {{1, 0}, {1, 1}}},
               {Kind::kRow, {{1, 1}, {1, 1}}},  // no length
               {Kind::kTransit, {{1, 1}, {0, 2}}},
               {Kind::kRow, {{0, 2}, {2, 2}}}};
  std::vector<std::uint32_t> starts;
  const nav_msgs::Path path = toPathMessage(plan, "map", ros::Time(1), &starts);
  ASSERT_EQ(path.poses.size(), 5u);
  EXPECT_EQ(starts, (std::vector<std::uint32_t>{0, 3}));
}

// Issue 44, item 2, over random requests in the furnished room: radii, swaths and starts.
TEST(CoverageRos, rows_answered_are_the_plans_rows_for_random_requests) {
  const CoverageDefaults d = furnished();
  std::mt19937 random(44);
  std::uniform_real_distribution<double> x(0.1, 6.3), y(0.1, 4.7), unit(0, 1);
  int planned = 0;
  for (int i = 0; i < 60; ++i) {
    PlanCoverage::Request request = from(x(random), y(random));
    request.robot_radius = 0.1 + 0.9 * unit(random);
    request.swath = 0.05 + (2 * request.robot_radius - 0.05) * unit(random);
    const PlanCoverage::Response r = planCoverage(request, d, ros::Time(1));
    if (!r.success) continue;  // a start inside the furniture, say
    ++planned;
    SCOPED_TRACE("request " + std::to_string(i));
    expectRowsAsAnswered(r);
  }
  EXPECT_GT(planned, 20);
}

TEST(CoverageRos, rviz_draws_the_rows_and_the_transits_apart) {
  using visualization_msgs::Marker;
  const PlanCoverage::Response r = planCoverage(from(1.0, 1.0), furnished(), ros::Time(3));
  ASSERT_TRUE(r.success) << r.message;
  const visualization_msgs::MarkerArray array = toMarkers(r);
  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers.front().action, Marker::DELETEALL);
  std::map<std::string, const Marker*> by_ns;
  for (std::size_t i = 1; i < array.markers.size(); ++i) {
    by_ns[array.markers[i].ns] = &array.markers[i];
    EXPECT_EQ(array.markers[i].header.frame_id, "map");
    EXPECT_EQ(array.markers[i].header.stamp, ros::Time(3));
  }
  ASSERT_TRUE(by_ns.count("rows") && by_ns.count("transits") && by_ns.count("row_starts") &&
              by_ns.count("start"));
  const Marker& rows = *by_ns["rows"];
  ASSERT_EQ(rows.points.size(), 2 * r.row_starts.size());
  for (std::size_t i = 0; i < r.row_starts.size(); ++i) {  // each row's two ends, in order
    EXPECT_EQ(rows.points[2 * i], r.path.poses[r.row_starts[i]].pose.position);
    EXPECT_EQ(rows.points[2 * i + 1], r.path.poses[r.row_starts[i] + 1].pose.position);
  }
  // Every other step of the path is a transit's.
  EXPECT_EQ(by_ns["transits"]->points.size(), 2 * (r.path.poses.size() - 1 - r.row_starts.size()));
  EXPECT_EQ(by_ns["row_starts"]->points.size(), r.row_starts.size());
  EXPECT_EQ(by_ns["start"]->pose.position, r.path.poses.front().pose.position);
  EXPECT_EQ(by_ns.count("room"), 0u);  // without the world
  // With the world it was planned in: its walls and its five pieces of furniture.
  world::World planned_in;
  const PlanCoverage::Response again =
      planCoverage(from(1.0, 1.0), furnished(), ros::Time(3), &planned_in);
  const visualization_msgs::MarkerArray drawn = toMarkers(again, &planned_in);
  int furniture = 0;
  const Marker* room = nullptr;
  for (const Marker& m : drawn.markers) {
    furniture += m.ns == "furniture";
    if (m.ns == "room") room = &m;
  }
  EXPECT_EQ(furniture, 5);
  ASSERT_NE(room, nullptr);
  ASSERT_EQ(room->points.size(), 5u);
  EXPECT_DOUBLE_EQ(room->points[2].x, 6.4);
  EXPECT_DOUBLE_EQ(room->points[2].y, 4.8);
  // A refusal clears what the last plan drew, and draws nothing.
  const visualization_msgs::MarkerArray none =
      toMarkers(planCoverage(from(1.3, 3.5), furnished(), ros::Time(4)));
  ASSERT_EQ(none.markers.size(), 1u);
  EXPECT_EQ(none.markers.front().action, Marker::DELETEALL);
}

TEST(CoverageRos, each_pose_faces_the_next) {
  const PlanCoverage::Response r = planCoverage(from(1.0, 1.0), furnished(), ros::Time(0));
  ASSERT_TRUE(r.success) << r.message;
  for (std::size_t k = 0; k + 1 < r.path.poses.size(); ++k) {
    const auto& p = r.path.poses[k].pose;
    const auto& q = r.path.poses[k + 1].pose.position;
    const double yaw = 2 * std::atan2(p.orientation.z, p.orientation.w);
    EXPECT_NEAR(std::cos(yaw),
                (q.x - p.position.x) / std::hypot(q.x - p.position.x, q.y - p.position.y), 1e-9);
  }
}

TEST(CoverageRos, a_region_is_planned_alone) {
  PlanCoverage::Request request = from(1.0, 1.5);
  request.x_min = 0.0;
  request.x_max = 3.2;
  request.y_min = 0.0;
  request.y_max = 4.8;
  const PlanCoverage::Response half = planCoverage(request, furnished(), ros::Time(0));
  ASSERT_TRUE(half.success) << half.message;
  const PlanCoverage::Response whole = planCoverage(from(1.0, 1.5), furnished(), ros::Time(0));
  EXPECT_LT(half.reachable_area, 0.6 * whole.reachable_area);
  for (const auto& pose : half.path.poses) {
    EXPECT_LE(pose.pose.position.x, 3.2 - 0.17);
  }
}

TEST(CoverageRos, another_robot_gets_rows_a_swath_of_its_own_apart) {
  PlanCoverage::Request request = from(1.0, 1.5);
  request.robot_radius = 0.25;
  const CoverageDefaults d = furnished();
  const PlanCoverage::Response r = planCoverage(request, d, ros::Time(0));
  ASSERT_TRUE(r.success) << r.message;
  world::World big = *d.room;
  big.robot().radius = 0.25;
  expectDrivable(big, r.path, 0.25 + d.clearance - 1e-6);
  const PlanCoverage::Response roomba = planCoverage(from(1.0, 1.5), d, ros::Time(0));
  EXPECT_LT(r.row_length, 0.8 * roomba.row_length);  // rows up to 0.49 m apart, not 0.335
}

TEST(CoverageRos, a_map_is_planned_once_one_has_arrived) {
  CoverageDefaults d = furnished();
  PlanCoverage::Request request = from(0.0, 0.0);
  request.world = "map";
  PlanCoverage::Response r = planCoverage(request, d, ros::Time(0));
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.message.rfind("world: ", 0), 0u) << r.message;
  geometry::MapFile map = geometry::loadMap(ROOMBA_RRT_CONFIG_DIR "/maps/apartment.yaml");
  d.map = std::make_shared<const world::World>(
      world::mapWorld(std::make_shared<const geometry::OccupancyGrid>(std::move(map.grid)), 0.17));
  r = planCoverage(request, d, ros::Time(0));
  ASSERT_TRUE(r.success) << r.message;
  expectDrivable(*d.map, r.path, 0.17 + d.clearance - 1e-6);
  EXPECT_GT(r.reachable_area, 20);
  EXPECT_GT(r.unreachable_area, 0);  // the apartment has corners and gaps the disc misses
}

// A bad request: success false, the message starting with the field, no path.
void expectRefused(const PlanCoverage::Request& request, const std::string& field) {
  const PlanCoverage::Response r = planCoverage(request, furnished(), ros::Time(0));
  EXPECT_FALSE(r.success) << field;
  EXPECT_EQ(r.message.rfind(field + ": ", 0), 0u) << r.message;
  EXPECT_TRUE(r.path.poses.empty());
  EXPECT_TRUE(r.row_starts.empty());
}

TEST(CoverageRos, a_bad_request_is_refused_naming_its_field) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PlanCoverage::Request r = from(1.0, 1.0);
  r.world = "moon";
  expectRefused(r, "world");
  expectRefused(from(nan, 1.0), "start.x");
  expectRefused(from(1.0, inf), "start.y");
  r = from(1.0, 1.0);
  r.start.z = nan;  // as plan_path refuses it
  expectRefused(r, "start.z");
  expectRefused(from(1.3, 3.5), "start");    // in the round table
  expectRefused(from(20.0, 1.0), "start");   // outside the room
  expectRefused(from(1e308, 1.0), "start");  // far outside
  r = from(1.0, 1.0);
  r.x_max = 20.0;
  r.y_max = 4.0;
  expectRefused(r, "x_min..y_max");  // beyond the room
  r.x_min = nan;
  expectRefused(r, "x_min..y_max");
  r = from(1.0, 1.0);
  r.x_max = 0.2;
  r.y_max = 4.0;
  expectRefused(r, "x_min..y_max");  // narrower than the robot
  r = from(1.0, 1.0);
  r.robot_radius = -0.1;
  expectRefused(r, "robot_radius");
  r.robot_radius = 3.0;  // does not fit in the room
  expectRefused(r, "robot_radius");
  r.robot_radius = nan;
  expectRefused(r, "robot_radius");
  r.robot_radius = 0.01;  // below the furnished room's 2.5 cm lattice
  expectRefused(r, "robot_radius");
  r = from(1.0, 1.0);
  r.clearance = 0.5;
  expectRefused(r, "clearance");
  r.clearance = -1;
  expectRefused(r, "clearance");
  r = from(1.0, 1.0);
  r.swath = 1.0;
  expectRefused(r, "swath");
  r.swath = 1e-9;
  expectRefused(r, "swath");
  r.swath = inf;
  expectRefused(r, "swath");
}

}  // namespace
}  // namespace roomba_rrt::coverage_node
