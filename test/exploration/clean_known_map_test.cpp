// A robot given a stale map of its home (known_map.h: the walls, not the furniture), in process:
// what the map makes of the known walls and floor (BuiltMap with a prior), the cleaning that
// plans on it at once and cuts its rows round the furniture the lidar shows (clean_known_map.h),
// goals driven with it (roomba_nav_eval --unknown --known-map), and the maps it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "coverage_run.h"
#include "nav_eval_run.h"
#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/exploration/clean_known_map.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::exploration {
namespace {

using geometry::OccupancyGrid;

const std::string kFurnished = ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml";
const std::string kFurnishedWalls = ROOMBA_RRT_CONFIG_DIR "/maps/furnished_walls.yaml";
const std::string kTree = ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml";

/// The seen-occupied cell whose square the robot's disc along `path` overlaps by more than a
/// millimetre, from kAroundRobot beyond `robot` on (where it stands may touch what it bumped);
/// "" when there is none.
std::string throughSeenOccupied(const BuiltMap& map, const coverage::Polyline& path,
                                const geometry::Point2& robot) {
  const double reach = map.robot().radius - 1e-3;
  const mapping::OccupancyMapper& mapper = map.mapper();
  const OccupancyGrid grid = mapper.grid();
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const int samples =
        std::max(1, static_cast<int>(geometry::distance(path[k], path[k + 1]) / 0.01));
    for (int s = 0; s <= samples; ++s) {
      const double t = static_cast<double>(s) / samples;
      const geometry::Point2 p{path[k].x + t * (path[k + 1].x - path[k].x),
                               path[k].y + t * (path[k + 1].y - path[k].y)};
      if (geometry::distance(p, robot) < CleanKnownMap::kAroundRobot) continue;
      for (int j = grid.row(p.y) - 5; j <= grid.row(p.y) + 5; ++j) {
        for (int i = grid.column(p.x) - 5; i <= grid.column(p.x) + 5; ++i) {
          const geometry::Rectangle square = grid.square(i, j);
          const geometry::Point2 centre{(square.min_x + square.max_x) / 2,
                                        (square.min_y + square.max_y) / 2};
          if (map.seenOccupied(centre) && geometry::squaredDistance(square, p) < reach * reach) {
            char where[96];
            std::snprintf(where, sizeof where, "cell (%.3f, %.3f) from (%.3f, %.3f)", centre.x,
                          centre.y, p.x, p.y);
            return where;
          }
        }
      }
    }
  }
  return "";
}

struct Cleaned {
  double reachable = 0;  ///< of the true reachable floor
  int bumps = 0;
  int plans = 0;
  std::vector<std::string> through;  ///< plans through a seen-occupied cell, where
};

/// The simulator in `world_file`, the robot given `known_map` and its lidar, for `duration`
/// simulated seconds, as roomba_coverage --unknown --known-map runs it; every plan checked as
/// the tree made it.
Cleaned cleanWithKnownMap(const std::string& world_file, const std::string& known_map,
                          double duration) {
  const world::World world = world::loadWorld(world_file);
  behavior::RoombaParams params =
      behavior::loadRoombaParams(ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml");
  params.rate = 1.0 / world.step;
  const tools::Cleaning truth(world, params);  // the true reachable floor, to measure against
  sim::Simulator simulator(world);
  sensors::Scanner scanner(world);
  CleanKnownMap robot(world.robot(), loadKnownMap(known_map), world.coverage_cell_size, params, 1,
                      0.0, kTree);
  Cleaned out;
  std::vector<robot::Pose2D> poses(1);
  bool was_pressed = false;
  int checked = 0;  // plans checked
  for (long k = 0; k < std::lround(duration / world.step); ++k) {
    const robot::BumperState bumper = simulator.senseContact();
    out.bumps += bumper.pressed && !was_pressed;
    was_pressed = bumper.pressed;
    poses[0] = simulator.pose();
    for (const sensors::Scan& scan : scanner.scan(k * world.step, poses)) {
      const sensors::RangeSensorSpec& spec = world.robot().sensors[scan.sensor];
      robot.addScan(mapping::mountedPose(poses[0], spec.mount),
                    mapping::scanView(spec, scan.ranges));
    }
    simulator.move(robot.tick(k * world.step, bumper, poses[0], k * world.step));
    // Each new tree's plan, as it was made, against the cells seen occupied then.
    const coverage::CoverageProgress* progress =
        coverage::findProgress(robot.activeTree()->tree().blackboard());
    if (progress && robot.plans() != checked) {
      checked = robot.plans();
      const std::string through = throughSeenOccupied(
          robot.map(), coverage::remainingPath(*progress), {poses[0].x, poses[0].y});
      if (!through.empty())
        out.through.push_back("plan " + std::to_string(robot.plans()) + ": " + through);
    }
  }
  const sim::CoverageGrid& grid = simulator.coverageGrid();
  out.reachable = std::min(
      1.0, grid.sweptFreeCells() * grid.cellSize() * grid.cellSize() / truth.reachable_area);
  out.plans = robot.plans();
  return out;
}

TEST(CleanKnownMap, cleans_the_furnished_room_from_its_map_without_the_furniture) {
  // The known map's rows at 213 s to 95 % (208 s knowing the furniture): 300 s is plenty.
  const Cleaned out = cleanWithKnownMap(kFurnished, kFurnishedWalls, 300);
  EXPECT_GE(out.reachable, 0.95);
  EXPECT_LE(out.bumps, 2);
  EXPECT_GT(out.plans, 1) << "the lidar showed the furniture in the way: the rows were cut";
  for (const std::string& through : out.through) ADD_FAILURE() << "planned through " << through;
}

TEST(CleanKnownMap, cleans_the_dining_room_between_its_chairs_from_its_walls) {
  const Cleaned out = cleanWithKnownMap(ROOMBA_RRT_TEST_DIR "/navigation/worlds/dining.yaml",
                                        ROOMBA_RRT_CONFIG_DIR "/maps/dining_walls.yaml", 300);
  EXPECT_GE(out.reachable, 0.95);  // 239 s to 95 % (215 s knowing the furniture)
  EXPECT_LE(out.bumps, 2);
  for (const std::string& through : out.through) ADD_FAILURE() << "planned through " << through;
}

/// A map of `width` × `height` cells of 0.05 m from (0, 0), all `value`.
std::shared_ptr<const OccupancyGrid> flatMap(int width, int height, std::int8_t value) {
  auto grid = std::make_shared<OccupancyGrid>();
  grid->resolution = 0.05;
  grid->width = width;
  grid->height = height;
  grid->cells.assign(static_cast<std::size_t>(width) * height, value);
  return grid;
}

TEST(BuiltMapPrior, known_walls_stay_walls_and_known_floor_is_floor_until_a_return_ends_there) {
  // 3 m x 2 m of known floor with a known wall across x in [1.5, 1.6].
  auto known = std::const_pointer_cast<OccupancyGrid>(flatMap(60, 40, OccupancyGrid::kFree));
  for (int j = 0; j < 40; ++j)
    known->cells[j * 60 + 30] = known->cells[j * 60 + 31] = OccupancyGrid::kOccupied;
  world::RobotSpec robot;
  robot.initial_pose = {0.5, 1.0, 0.0};
  BuiltMap map(robot, known);
  auto at = [](const OccupancyGrid& g, double x, double y) { return g.at(g.column(x), g.row(y)); };
  OccupancyGrid grid = map.grid(BuiltMap::Unknown::kWall);
  EXPECT_EQ(at(grid, 2.5, 1.0), OccupancyGrid::kFree) << "known floor, never seen";
  EXPECT_EQ(at(grid, 1.55, 1.0), OccupancyGrid::kOccupied) << "the known wall";
  // A ray along y = 1.0 reading nothing within 5 m passes the known wall: it stays a wall.
  // One ending at x = 1.2 (a chair the map lacks) makes its cell occupied for good.
  const float ranges[] = {std::numeric_limits<float>::infinity(), 0.7f};
  mapping::ScanView scan;
  scan.angle_min = 0;
  scan.angle_max = 0;
  scan.angle_increment = 0;
  scan.range_min = 0.1;
  scan.range_max = 5;
  scan.ranges = ranges;
  scan.count = 1;
  ASSERT_EQ(map.addScan({0.5, 1.0, 0.0}, scan), "");
  scan.ranges = ranges + 1;
  ASSERT_EQ(map.addScan({0.5, 1.0, 0.0}, scan), "");
  grid = map.grid(BuiltMap::Unknown::kWall);
  EXPECT_EQ(at(grid, 1.55, 1.0), OccupancyGrid::kOccupied) << "a ray through a known wall";
  EXPECT_EQ(at(grid, 1.225, 1.0), OccupancyGrid::kOccupied) << "the chair";
  EXPECT_TRUE(map.seenOccupied({1.225, 1.0}));
  for (int n = 0; n < 20; ++n) {  // rays that pass it later do not make it floor again
    scan.ranges = ranges;
    map.addScan({0.5, 1.025, 0.0}, scan);
  }
  EXPECT_EQ(at(map.grid(BuiltMap::Unknown::kWall), 1.225, 1.0), OccupancyGrid::kOccupied);
  // A bump on known floor: the cell it pressed is occupied.
  EXPECT_EQ(at(map.grid(BuiltMap::Unknown::kWall), 0.5, 0.5 + robot.radius + 0.01),
            OccupancyGrid::kFree);
  map.addBump({0.5, 0.5, M_PI / 2}, {true, true, true});
  EXPECT_TRUE(map.seenOccupied({0.5, 0.5 + robot.radius + 0.01}));
  EXPECT_EQ(at(map.grid(BuiltMap::Unknown::kWall), 0.5, 0.5 + robot.radius + 0.01),
            OccupancyGrid::kOccupied);
  // Navigation plans unknown cells as floor, never the known wall.
  EXPECT_EQ(at(map.grid(BuiltMap::Unknown::kFree), 1.55, 0.2), OccupancyGrid::kOccupied);
}

/// Writes `text` to a file in the test's temporary folder and returns its path.
std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// The field a known map is refused for, by loadKnownMap or checkKnownMap for the furnished
/// room's robot; "accepted" when it is not refused.
std::string refusedField(const std::string& file) {
  try {
    checkKnownMap(loadKnownMap(file), world::loadWorld(kFurnished).robot());
  } catch (const util::InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    return e.field().empty() ? std::string(e.what()) : e.field();
  }
  return "accepted";
}

TEST(KnownMap, refuses_a_map_that_cannot_be_this_home_naming_the_field) {
  EXPECT_EQ(refusedField(kFurnishedWalls), "accepted");
  EXPECT_EQ(refusedField(kFurnished), "accepted");  // a world file: drawn
  const std::string pgm = ROOMBA_RRT_CONFIG_DIR "/maps/furnished_walls.pgm";
  auto yaml = [&](const std::string& resolution, const std::string& origin) {
    return "image: " + pgm + "\nresolution: " + resolution + "\norigin: " + origin +
           "\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  };
  EXPECT_EQ(refusedField(writeFile("nan.yaml", yaml(".nan", "[-0.1, -0.1, 0.0]"))), "resolution");
  EXPECT_EQ(refusedField(writeFile("coarse.yaml", yaml("0.2", "[-0.4, -0.4, 0.0]"))), "resolution");
  // The room drawn 10 m away (another frame): the robot's start is off it.
  EXPECT_EQ(refusedField(writeFile("far.yaml", yaml("0.05", "[10.0, 10.0, 0.0]"))), "origin");
  // Shifted by 3.2 m: the start lands on the wall.
  EXPECT_EQ(refusedField(writeFile("shifted.yaml", yaml("0.05", "[-3.3, -0.1, 0.0]"))), "origin");
  EXPECT_EQ(refusedField(writeFile("rotated.yaml", yaml("0.05", "[-0.1, -0.1, 0.5]"))),
            "origin[2]");
  EXPECT_EQ(refusedField(writeFile("nan_world.yaml",
                                   "room: {width: 6.4, height: 4.8}\nfurniture:\n  circles:\n"
                                   "    - {x: .nan, y: 1.0, radius: 0.2}\n")),
            "furniture.circles[0].x");
  const std::string missing = ::testing::TempDir() + "no_such_map.yaml";
  EXPECT_NE(refusedField(missing), "accepted");
}

TEST(NavigateKnownMap, reaches_random_goals_in_the_office_from_its_walls_without_a_bump) {
  tools::NavEvalOptions options;
  options.goals = 30;
  options.seed = 3;
  options.unknown = true;
  options.known_map = ROOMBA_RRT_CONFIG_DIR "/maps/office_walls.yaml";
  const tools::NavEvalReport r = tools::evaluateNavigation(
      world::loadWorld(ROOMBA_RRT_TEST_DIR "/navigation/worlds/office.yaml"),
      ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml", options);
  EXPECT_GE(r.reached_pct, 99.0);  // 200 of 200 in doc/navigation.md
  EXPECT_EQ(r.bumps, 0);
}

TEST(NavigateKnownMap, the_first_path_to_the_room_behind_the_wall_goes_through_the_door) {
  const world::World world = world::loadWorld(ROOMBA_RRT_TEST_DIR "/tools/worlds/two_rooms.yaml");
  const robot::Pose2D goal{6.5, 3.0, 0.0};
  auto drive = [&](const KnownMap* known) {
    sim::Simulator simulator(world);
    sensors::Scanner scanner(world);
    double clock = 0;
    return tools::driveUnknown(simulator, scanner, ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml",
                               goal, 1, 120, clock, known);
  };
  // The two rooms' walls and door, without the plant: the way through the door is known.
  const std::string walls = writeFile("two_rooms_walls.yaml",
                                      "room: {width: 8.0, height: 4.0}\nfurniture:\n  rectangles:\n"
                                      "    - {min_x: 3.9, min_y: 0.0, max_x: 4.1, max_y: 1.75}\n"
                                      "    - {min_x: 3.9, min_y: 2.25, max_x: 4.1, max_y: 4.0}\n");
  const KnownMap known = loadKnownMap(walls);
  const tools::GoalRun with_map = drive(&known);
  const tools::GoalRun without = drive(nullptr);
  EXPECT_TRUE(with_map.reached) << with_map.message;
  EXPECT_EQ(with_map.bumps, 0);
  EXPECT_EQ(with_map.plans, 1) << "the known wall was planned through";
  EXPECT_GT(without.plans, 1);  // without the map the first path went through the wall
}

}  // namespace
}  // namespace roomba_rrt::exploration
