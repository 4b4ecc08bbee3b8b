// roomba_nav_eval's core: the independent shortest length for the robot's disc, and the goal
// loop (deterministic by seed, goals reached without bumps in the furnished room).
#include <gtest/gtest.h>

#include <cmath>

#include "nav_eval_run.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::tools {
namespace {

world::World emptyRoom() {
  world::World world;
  world.room.width = 4;
  world.room.height = 4;
  world.robot().radius = 0.2;
  return world;
}

TEST(ShortestDiscPath, is_the_straight_line_when_nothing_is_in_the_way) {
  EXPECT_DOUBLE_EQ(shortestDiscPathLength(emptyRoom(), {1, 1, 0}, {3, 2, 0}), std::hypot(2, 1));
}

TEST(ShortestDiscPath, goes_around_a_disc_within_one_percent_of_the_exact_length) {
  world::World world = emptyRoom();
  world.room.circles = {{2, 2, 0.5}};
  // Start and goal on either side: the exact shortest path hugs the grown disc (radius 0.7):
  // two tangents and an arc.
  const double R = 0.7, d = 1.5;  // distance from the centre to start and goal
  const double tangent = std::sqrt(d * d - R * R);
  const double arc = R * (M_PI - 2.0 * std::acos(R / d));
  const double exact = 2 * tangent + arc;
  const double length = shortestDiscPathLength(world, {0.5, 2, 0}, {3.5, 2, 0});
  EXPECT_GE(length, exact - 1e-9);
  EXPECT_LE(length, exact * 1.01);
}

TEST(ShortestDiscPath, goes_around_a_rectangle_and_is_infinite_when_walled_off) {
  world::World world = emptyRoom();
  world.room.rectangles = {{1.9, 0.0, 2.1, 3.0}};  // a wall from the bottom, gap of 1 m at the top
  const double length = shortestDiscPathLength(world, {1, 1, 0}, {3, 1, 0});
  // Exact: a tangent to each rounded corner (centres (1.9, 3) and (2.1, 3), radius 0.2), the
  // arcs around them and the 0.2 m over the top.
  const double r = 0.2, d = std::hypot(0.9, 2.0);
  const double turn = std::atan2(2.0, 0.9) + std::asin(r / d);  // tangent's angle to the x axis
  const double exact = 2 * std::sqrt(d * d - r * r) + 2 * r * turn + 0.2;
  EXPECT_GE(length, exact - 1e-9);
  EXPECT_LE(length, exact * 1.01);
  world.room.rectangles = {{1.9, 0.0, 2.1, 4.0}};
  EXPECT_TRUE(std::isinf(shortestDiscPathLength(world, {1, 1, 0}, {3, 1, 0})));
}

TEST(NavEval, reaches_random_goals_in_the_furnished_room_without_a_bump_and_repeats_by_seed) {
  const world::World world = world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml");
  NavEvalOptions options;
  options.goals = 10;
  options.seed = 7;
  const std::string tree = ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml";
  const NavEvalReport a = evaluateNavigation(world, tree, options);
  EXPECT_EQ(a.reached_pct, 100.0);
  EXPECT_EQ(a.bumps, 0);
  EXPECT_GE(a.mean_length_ratio, 0.95);  // the robot stops within 5 cm of the goal
  EXPECT_LE(a.mean_length_ratio, 1.2);
  const NavEvalReport b = evaluateNavigation(world, tree, options);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    EXPECT_EQ(a.runs[i].goal.x, b.runs[i].goal.x);
    EXPECT_EQ(a.runs[i].driven_m, b.runs[i].driven_m);
  }
  const std::string json = toJson(a);
  for (const char* key : {"\"goals\": 10", "\"reached_pct\"", "\"bumps\"", "\"mean_time_s\"",
                          "\"mean_length_ratio\"", "\"planning_ms_p50\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << json;
  }
}

}  // namespace
}  // namespace roomba_rrt::tools
