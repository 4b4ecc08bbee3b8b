// The classic Roomba (bumper and IR light bumper, no lidar) cleaning a home it has never seen,
// in process as roomba_coverage --unknown runs it (exploration/bump_clean.h): the simulator, the
// IR light bumper's scans, the bumper, the online boustrophedon.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

#include "coverage_run.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/exploration/bump_clean.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/sensors/range_sensor.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::tools {
namespace {

behavior::RoombaParams labParams(const world::World& world) {
  behavior::RoombaParams params =
      behavior::loadRoombaParams(ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml");
  params.rate = 1.0 / world.step;
  return params;
}

/// `file` with the IR light bumper as the robot's only range sensor.
world::World irOnly(const std::string& file) {
  world::World world = world::loadWorld(file);
  world.robot().sensors = {sensors::irBumperPreset(world.robot().radius)};
  return world;
}

struct Outcome {
  Run run;
  double ideal_time = 0;
};

/// Where the run reports its coverage at 3× the ideal time (kIdealMultiples).
constexpr std::size_t kAt3x = std::size(kIdealMultiples) - 1;
static_assert(kIdealMultiples[kAt3x] == 3.0);

/// roomba_coverage --behavior coverage --unknown for 3× the ideal time (or `duration`).
Outcome cleanByTouch(const world::World& world, double duration = 0) {
  const behavior::RoombaParams params = labParams(world);
  const Cleaning cleaning(world, params);  // the true reachable floor, to measure against
  CoverageArguments o;
  o.behavior = "unknown";
  o.duration = duration > 0 ? duration : 3 * cleaning.ideal_time + 1;
  sim::Simulator simulator(world);
  Outcome out{simulate(o, params, 1, nullptr, false, simulator, &cleaning), cleaning.ideal_time};
  std::printf("  %.1f %% at 3x ideal (%.0f s), %.1f %% at the end, %d bumps, done at %.0f s\n",
              out.run.at_ideal.size() > kAt3x ? 100 * out.run.at_ideal[kAt3x] : NAN,
              3 * out.ideal_time, 100 * out.run.reachable_final, out.run.bumps, out.run.done_at);
  return out;
}

TEST(BumpClean, a_robot_without_a_lidar_cleans_by_touch) {
  world::World world = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  EXPECT_FALSE(exploration::cleansByTouch(world.robot())) << "the LDS reaches 3.5 m";
  world.robot().sensors = {sensors::irBumperPreset(world.robot().radius)};
  EXPECT_TRUE(exploration::cleansByTouch(world.robot())) << "the IR light bumper 0.15 m";
  world.robot().sensors.clear();
  EXPECT_TRUE(exploration::cleansByTouch(world.robot())) << "the bumper alone";
  // A robot with its bumper alone is cleaned by touch too, not refused.
  const Outcome out = cleanByTouch(world, 30);
  EXPECT_TRUE(out.run.by_touch);
  EXPECT_GT(out.run.reachable_final, 0.05);
}

TEST(BumpClean, cleans_a_furnished_room_it_has_never_seen_90_percent_by_three_times_ideal) {
  const Outcome out = cleanByTouch(irOnly(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"));
  ASSERT_EQ(out.run.at_ideal.size(), std::size(kIdealMultiples));
  EXPECT_GE(out.run.at_ideal[kAt3x], 0.90);
  EXPECT_TRUE(out.run.by_touch);
}

TEST(BumpClean, finds_the_narrow_door_and_cleans_the_room_behind_it) {
  const Outcome out = cleanByTouch(irOnly(ROOMBA_RRT_TEST_DIR "/tools/worlds/two_rooms.yaml"));
  // Half the floor lies behind the 0.5 m door (the disc is 0.34 m): without it at most 50 %.
  EXPECT_GE(out.run.reachable_final, 0.90);
}

TEST(BumpClean, finishes_when_no_floor_it_can_reach_is_left) {
  const world::World world = irOnly(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml");  // the lab's
  const Outcome out = cleanByTouch(world, 1500);
  ASSERT_TRUE(std::isfinite(out.run.done_at)) << "still cleaning after 1500 s";
  EXPECT_GE(out.run.reachable_final, 0.95);
}

/// Drives BumpClean in the simulator and checks each move it plans when it plans it: the transit
/// and the move's start keep reach() from every point found so far (but those it stands beside),
/// and a move from where it stands does not drive into one.
TEST(BumpClean, never_plans_through_what_it_has_found) {
  for (const char* file : {ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml",
                           ROOMBA_RRT_TEST_DIR "/navigation/worlds/dining.yaml"}) {
    SCOPED_TRACE(file);
    const world::World world = irOnly(file);
    const behavior::RoombaParams params = labParams(world);
    sim::Simulator simulator(world);
    sensors::Scanner scanner(world);
    exploration::BumpClean clean(world.robot(), params);
    const sensors::RangeSensorSpec& ir = world.robot().sensors.front();
    int checked = 0, seen_moves = 0;
    for (long k = 0; k < std::lround(400 / world.step) && !clean.done(); ++k) {
      const robot::Pose2D pose = simulator.pose();
      for (const sensors::Scan& scan : scanner.scan(k * world.step, {pose})) {
        clean.addScan(mapping::mountedPose(pose, ir.mount), mapping::scanView(ir, scan.ranges));
      }
      simulator.move(clean.tick(k * world.step, simulator.senseContact(), pose));
      if (clean.moves() == seen_moves) continue;
      seen_moves = clean.moves();
      const exploration::Move& move = *clean.move();
      const exploration::SweptMap& map = clean.map();
      const std::vector<geometry::Point2> points = map.points();
      if (move.transit.empty()) {
        // From where the robot stands (it may be pressed against what it found): away from it.
        EXPECT_GT(map.freeLength(move.start, exploration::unit(move.heading), 1.0), 0.01)
            << "move " << seen_moves << " drives into a point it found";
        continue;
      }
      EXPECT_FALSE(map.blocked(map.cellOf(move.start)))
          << "move " << seen_moves << " starts within reach of a point it found";
      for (std::size_t leg = 1; leg < move.transit.size(); ++leg) {
        const geometry::Segment s{move.transit[leg - 1], move.transit[leg]};
        for (const geometry::Point2& p : points) {
          // The robot leaves what it is pressed against (within reach of where it stands).
          if (geometry::distance(p, move.transit.front()) < map.reach()) continue;
          ASSERT_GE(geometry::distance(p, geometry::closestPoint(s, p)),
                    map.reach() - map.resolution())
              << "move " << seen_moves << ": transit leg " << leg << " passes (" << p.x << ", "
              << p.y << ")";
        }
        ++checked;
      }
    }
    EXPECT_GT(checked, 20) << "too few transits to tell";
  }
}

}  // namespace
}  // namespace roomba_rrt::tools
