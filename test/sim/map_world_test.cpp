// The simulator in a map: a map_server YAML as the world (or named by a world file's `map:`),
// its occupied and unknown cells walls against which contact is exact, at a wall's face, a
// corner and a one-cell gap; the coverage counts the map's free floor; random driving in a real
// map never ends a step inside a wall.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "../common/shared_maps.h"
#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

using namespace roomba_rrt;

namespace {

namespace fs = std::filesystem;

/// A folder with a map drawn in text (top row first: '#' black, '?' grey, '.' white) as a PGM
/// and its map_server YAML (resolution 0.05 m, origin (-1, -0.5)).
class MapWorld : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(testing::TempDir()) /
           ("map_world_test_" +
            std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string draw(const std::vector<std::string>& rows) {
    std::string pixels;
    for (const std::string& row : rows) {
      for (const char c : row) pixels += c == '#' ? '\0' : c == '?' ? '\x80' : '\xff';
    }
    std::ofstream(dir_ / "m.pgm", std::ios::binary)
        << "P5\n"
        << rows[0].size() << " " << rows.size() << "\n255\n"
        << pixels;
    const fs::path yaml = dir_ / "m.yaml";
    std::ofstream(yaml) << "image: m.pgm\nresolution: 0.05\norigin: [-1.0, -0.5, 0.0]\n"
                           "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    return yaml.string();
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }

  fs::path dir_;
};

/// 40 x 30 cells (2 m x 1.5 m): walls all round, a wall at column 20 with a one-cell gap at row
/// 10 (from the top), a grey (unknown) block.
std::vector<std::string> roomWithAWall() {
  std::vector<std::string> rows(30, "#" + std::string(38, '.') + "#");
  rows.front() = rows.back() = std::string(40, '#');
  for (int j = 1; j < 29; ++j) {
    if (j != 10) rows[j][20] = '#';
  }
  for (int j = 20; j < 24; ++j) rows[j].replace(5, 4, "????");
  return rows;
}

TEST_F(MapWorld, a_map_yaml_is_a_world_whose_room_is_the_map) {
  const std::string yaml = draw(roomWithAWall());
  std::string error;
  try {
    world::loadWorld(yaml);
  } catch (const util::InvalidInput& e) {
    error = e.what();
  }
  // The default pose is the map's origin (0, 0): column 20 is the wall there.
  EXPECT_NE(error.find("initial_pose: (0, 0) puts the robot's disc inside a wall"),
            std::string::npos)
      << error;
  const std::string world_file =
      write("w.yaml", "map: m.yaml\ninitial_pose: {x: -0.5, y: 0.25, theta: 0}\n");
  const world::World w = world::loadWorld(world_file);
  ASSERT_TRUE(w.room.map);
  EXPECT_DOUBLE_EQ(w.room.origin.x, -1.0);
  EXPECT_DOUBLE_EQ(w.room.origin.y, -0.5);
  EXPECT_DOUBLE_EQ(w.room.width, 2.0);
  EXPECT_DOUBLE_EQ(w.room.height, 1.5);
  EXPECT_EQ(w.room.map_file, (dir_ / "m.yaml").string());
  EXPECT_THROW(world::loadWorld(write("r.yaml", "map: m.yaml\nroom: {width: 3, height: 3}\n")),
               util::InvalidInput);
  try {
    world::loadWorld(write("bad.yaml", "map: missing.yaml\n"));
    FAIL();
  } catch (const util::InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir_ / "bad.yaml").string() + ": map: ", 0), 0u)
        << e.what();
  }
}

TEST_F(MapWorld, a_slam_maps_unknown_border_is_not_part_of_the_room) {
  // The room of roomWithAWall() in an image four times as wide and three times as high, the rest
  // unknown, as gmapping saves a flat in its 4000 x 4000 cells.
  std::vector<std::string> rows(90, std::string(160, '?'));
  const std::vector<std::string> room = roomWithAWall();
  for (std::size_t j = 0; j < room.size(); ++j) rows[40 + j].replace(70, 40, room[j]);
  draw(rows);  // origin (-1, -0.5): the room's cells 70..109 x 20..49 (rows from the bottom)
  const world::World w =
      world::loadWorld(write("w.yaml", "map: m.yaml\ninitial_pose: {x: 3.2, y: 1.6, theta: 0}\n"));
  EXPECT_DOUBLE_EQ(w.room.origin.x, -1.0 + 70 * 0.05);
  EXPECT_DOUBLE_EQ(w.room.origin.y, -0.5 + 20 * 0.05);
  EXPECT_NEAR(w.room.width, 2.0, 1e-12);
  EXPECT_NEAR(w.room.height, 1.5, 1e-12);
  EXPECT_EQ(w.coverage_cell_size, 0.025);  // the room's, not the image's 8 m x 4.5 m
  // The whole image can still be named when cutting a region; what is kept is the room's part.
  const world::World part = world::cropped(w, {-1.0, -0.5, 3.5, 1.5}, "--crop");
  EXPECT_DOUBLE_EQ(part.room.origin.x, w.room.origin.x);
  EXPECT_NEAR(part.room.origin.x + part.room.width, 3.5, 1e-12);
  EXPECT_NEAR(part.room.origin.y + part.room.height, 1.5, 1e-12);
  EXPECT_THROW(world::cropped(w, {-1.0, -0.5, 2.0, 0.4}, "--crop"), util::InvalidInput);
  // Driving: the same walls as the room alone (its inner wall at its column 20).
  sim::Simulator sim(w);
  for (int i = 0; i < 120; ++i) sim.step({0.5, 0.0});
  EXPECT_NEAR(sim.pose().x, w.room.origin.x + 20 * 0.05 - w.robot().radius, 1e-9);
}

TEST_F(MapWorld, a_region_is_kept_in_whole_cells_inside_it) {
  // The coverage lattice starts at the region's corner: cut on whole cells, its walls lie between
  // lattice points, as the map's own do, and no floor is left within the rows' clearance of them.
  draw(roomWithAWall());  // origin (-1, -0.5), 5 cm cells, the room (-1, -0.5) to (1, 1)
  const world::World w =
      world::loadWorld(write("w.yaml", "map: m.yaml\ninitial_pose: {x: -0.5, y: 0.6, theta: 0}\n"));
  const world::World part = world::cropped(w, {-0.98, -0.47, 0.93, 0.96}, "--crop");
  EXPECT_NEAR(part.room.origin.x, -0.95, 1e-12);  // in, to the map's grid
  EXPECT_NEAR(part.room.origin.y, -0.45, 1e-12);
  EXPECT_EQ(part.coverage_cell_size, 0.025);
  EXPECT_NEAR(part.room.width, 75 * 0.025, 1e-12);   // 1.88 m: 75 whole cells of the lattice
  EXPECT_NEAR(part.room.height, 56 * 0.025, 1e-12);  // 1.41 m
  // A room without a map: its corner stays, the size shrinks to whole cells unless it reaches
  // the room's wall.
  world::World room;
  room.room.width = 2.0;
  room.room.height = 1.5;
  const world::World in_room = world::cropped(room, {0.013, 0.02, 1.9, 1.5}, "--crop");
  EXPECT_DOUBLE_EQ(in_room.room.origin.x, 0.013);
  EXPECT_DOUBLE_EQ(in_room.room.origin.y, 0.02);
  EXPECT_NEAR(in_room.room.width, 75 * 0.025, 1e-12);  // 1.887 m
  EXPECT_NEAR(in_room.room.height, 1.48, 1e-12);       // to the room's top wall, where it was asked
  // Wider than the robot (0.34 m) as asked, 0.33 m once on the map's grid: refused.
  EXPECT_THROW(world::cropped(w, {-0.98, -0.47, -0.62, 0.5}, "--crop"), util::InvalidInput);
}

TEST_F(MapWorld, driving_into_a_wall_of_cells_stops_exactly_at_its_face_with_both_switches) {
  draw(roomWithAWall());
  const world::World w =
      world::loadWorld(write("w.yaml", "map: m.yaml\ninitial_pose: {x: -0.5, y: 0.6, theta: 0}\n"));
  sim::Simulator sim(w);
  robot::BumperState bumper;
  for (int i = 0; i < 120; ++i) bumper = sim.step({0.5, 0.0});
  // The wall's cells start at x = -1 + 20 * 0.05 = 0.
  EXPECT_NEAR(sim.pose().x, 0.0 - w.robot().radius, 1e-9);
  EXPECT_NEAR(sim.pose().y, 0.6, 1e-9);  // no sideways nudge at the seams between cells
  EXPECT_TRUE(bumper.pressed);
  EXPECT_TRUE(bumper.left);
  EXPECT_TRUE(bumper.right);
}

TEST_F(MapWorld, a_gap_narrower_than_the_robot_is_never_passed_and_nothing_overlaps) {
  draw(roomWithAWall());
  // Head for the one-cell (5 cm) gap at row 10 from the top: y = -0.5 + (29 - 10 + 0.5) * 0.05.
  const double gap_y = -0.5 + 19.5 * 0.05;
  const world::World w = world::loadWorld(
      write("w.yaml",
            "map: m.yaml\ninitial_pose: {x: -0.5, y: " + std::to_string(gap_y) + ", theta: 0}\n"));
  sim::Simulator sim(w);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> turn(-2.0, 2.0);
  for (int i = 0; i < 20000; ++i) {
    sim.step({0.5, i % 200 < 150 ? 0.0 : turn(rng)});
    ASSERT_FALSE(world::penetrates(w, sim.pose().x, sim.pose().y)) << "step " << i;
    ASSERT_LT(sim.pose().x, 0.0) << "passed the 5 cm gap at step " << i;
  }
}

TEST_F(MapWorld, coverage_counts_the_free_floor_of_the_map) {
  const std::vector<std::string> rows = roomWithAWall();
  draw(rows);
  const world::World w =
      world::loadWorld(write("w.yaml", "map: m.yaml\ninitial_pose: {x: -0.5, y: 0.6, theta: 0}\n"));
  long free_cells = 0;
  for (const std::string& row : rows) free_cells += std::count(row.begin(), row.end(), '.');
  const sim::Simulator sim(w);
  // 2.5 cm coverage cells: four in each 5 cm map cell.
  EXPECT_EQ(sim.coverageGrid().freeCells(), 4 * free_cells);
}

TEST(SharedMapWorld, random_driving_in_a_real_map_never_ends_a_step_inside_a_wall) {
  ROOMBA_RRT_REQUIRE_SHARED_MAP("turtlebot3_world");
  const fs::path map = ::roomba_rrt::test::sharedMapPath("turtlebot3_world");
  // TurtleBot3's start pose in its world.
  const fs::path world_file = fs::path(testing::TempDir()) / "turtlebot3_world_test.yaml";
  std::ofstream(world_file) << "map: " << map.string()
                            << "\ninitial_pose: {x: -2.0, y: -0.5, theta: 0}\n";
  const world::World w = world::loadWorld(world_file.string());
  sim::Simulator sim(w);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> v(-0.3, 1.0), turn(-2.0, 2.0);
  robot::Velocity cmd;
  int bumps = 0;
  for (int i = 0; i < 100000; ++i) {
    if (i % 30 == 0) cmd = {v(rng), turn(rng)};
    bumps += sim.step(cmd).pressed;
    ASSERT_FALSE(world::penetrates(w, sim.pose().x, sim.pose().y)) << "step " << i;
  }
  EXPECT_GT(bumps, 0);  // it did meet the walls
}

}  // namespace
