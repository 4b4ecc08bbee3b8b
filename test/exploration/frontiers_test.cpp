// Frontiers on small hand-made maps: what a robot exploring an unseen home must get right.
#include "roomba_rrt/exploration/frontiers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace roomba_rrt::exploration {
namespace {

using geometry::OccupancyGrid;

/// A map from rows of text, the first row at the top: '#' occupied, '.' free, '?' unknown;
/// 0.1 m cells, origin (0, 0).
std::shared_ptr<const OccupancyGrid> mapOf(const std::vector<std::string>& rows) {
  auto map = std::make_shared<OccupancyGrid>();
  map->height = static_cast<int>(rows.size());
  map->width = static_cast<int>(rows.front().size());
  map->resolution = 0.1;
  map->cells.resize(static_cast<std::size_t>(map->width) * map->height);
  for (int j = 0; j < map->height; ++j) {
    const std::string& row = rows[map->height - 1 - j];
    for (int i = 0; i < map->width; ++i) {
      map->cells[static_cast<std::size_t>(j) * map->width + i] =
          row[i] == '#'   ? OccupancyGrid::kOccupied
          : row[i] == '?' ? OccupancyGrid::kUnknown
                          : OccupancyGrid::kFree;
    }
  }
  return map;
}

/// A free room `w` × `h` cells inside a wall, its columns from `unknown_from` on unknown.
std::vector<std::string> room(int w, int h, int unknown_from) {
  std::vector<std::string> rows(h, std::string(w, '.'));
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      if (i >= unknown_from) rows[j][i] = '?';
      if (i == 0 || j == 0 || j == h - 1 || (i == w - 1 && unknown_from >= w)) rows[j][i] = '#';
    }
  }
  return rows;
}

FrontierOptions options() {
  FrontierOptions o;
  o.robot_radius = 0.17;
  o.view_distance = 0.5;
  o.min_cells = 3;
  return o;
}

TEST(Frontiers, a_room_seen_whole_has_none_and_the_exploration_is_done) {
  const auto map = mapOf(room(30, 20, 30));
  const auto frontiers = findFrontiers(*map, 3);
  EXPECT_TRUE(frontiers.empty());
  const geometry::ClearanceMap known(map);
  EXPECT_FALSE(nearestFrontier(known, {1.5, 1.0}, frontiers, options()).has_value());
}

TEST(Frontiers, the_free_cells_beside_the_unknown_are_one_frontier_reached_from_its_view_distance) {
  const auto map = mapOf(room(60, 20, 40));  // columns 40.. unknown
  const auto frontiers = findFrontiers(*map, 3);
  ASSERT_EQ(frontiers.size(), 1u);
  EXPECT_EQ(frontiers[0].cells.size(), 18u);  // column 39, rows 1..18
  EXPECT_NEAR(frontiers[0].centroid.x, 3.95, 1e-9);
  const geometry::ClearanceMap known(map);
  const auto goal = nearestFrontier(known, {0.5, 1.0}, frontiers, options());
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(goal->frontier, 0);
  // It stops as soon as the frontier is in view: 0.5 m before column 39's centres.
  EXPECT_NEAR(goal->goal.x, 3.45, 1e-9);
  EXPECT_GT(goal->path_length, 2.9);
  EXPECT_TRUE(known.discFree(goal->goal, known.disc(0.17)));
}

TEST(Frontiers, gaps_between_rays_smaller_than_min_cells_are_not_frontiers) {
  auto rows = room(30, 20, 30);
  rows[10][15] = '?';  // one unseen cell in the middle of the floor
  const auto map = mapOf(rows);
  EXPECT_TRUE(findFrontiers(*map, 5).empty());
  EXPECT_EQ(findFrontiers(*map, 1).size(), 1u);
}

TEST(Frontiers, the_nearest_is_the_nearest_by_the_way_there_not_through_a_wall) {
  // A wall at column 15 from the floor up to row 14 (rows counted from the bottom). Unknown A:
  // columns 10..14, rows 1..5, just behind the wall from the robot at (2.0, 0.6); unknown B:
  // columns 44..48, straight ahead, 2.3 m away with nothing between.
  auto rows = room(50, 24, 50);  // 0.8 m above the wall's end: the lattice passes
  auto at = [&rows](int i, int j) -> char& { return rows[rows.size() - 1 - j][i]; };
  for (int j = 1; j <= 14; ++j) at(15, j) = '#';
  for (int j = 1; j <= 5; ++j) {
    for (int i = 10; i <= 14; ++i) at(i, j) = '?';
  }
  for (int j = 1; j <= 22; ++j) {
    for (int i = 44; i <= 48; ++i) at(i, j) = '?';
  }
  const auto map = mapOf(rows);
  const auto frontiers = findFrontiers(*map, 3);
  ASSERT_EQ(frontiers.size(), 2u);
  const geometry::ClearanceMap known(map);
  const auto goal = nearestFrontier(known, {2.0, 0.6}, frontiers, options());
  ASSERT_TRUE(goal.has_value());
  EXPECT_GT(frontiers[goal->frontier].centroid.x, 4.0) << "chose the frontier behind the wall";
  EXPECT_NEAR(goal->path_length, 3.85 - 2.05, 0.15);
  // Without B, A is the goal, reached round the wall's end (over 2 m of way for 0.5 m of line).
  const std::vector<Frontier> only_a = {frontiers[goal->frontier == 0 ? 1 : 0]};
  const auto round = nearestFrontier(known, {2.0, 0.6}, only_a, options());
  ASSERT_TRUE(round.has_value());
  EXPECT_LT(round->goal.x, 1.5) << "A is seen from its own side of the wall";
  EXPECT_GT(round->path_length, 2.0);
}

TEST(Frontiers, a_frontier_behind_a_gap_narrower_than_the_robot_is_not_reachable) {
  // A wall across the room with a 0.2 m gap (the robot is 0.34 m wide); unknown beyond it.
  auto rows = room(60, 20, 45);
  for (int j = 1; j < 19; ++j) rows[j][30] = '#';
  rows[9][30] = rows[10][30] = '.';
  const auto map = mapOf(rows);
  const auto frontiers = findFrontiers(*map, 3);
  ASSERT_EQ(frontiers.size(), 1u);
  const geometry::ClearanceMap known(map);
  EXPECT_FALSE(nearestFrontier(known, {1.0, 1.0}, frontiers, options()).has_value());
  // Widened to 0.6 m it is.
  for (int j = 7; j <= 12; ++j) rows[j][30] = '.';
  const auto wide = mapOf(rows);
  const geometry::ClearanceMap wide_known(wide);
  EXPECT_TRUE(nearestFrontier(wide_known, {1.0, 1.0}, findFrontiers(*wide, 3), options()));
}

TEST(Frontiers, unknown_cells_are_walls_until_seen) {
  // The only way to the frontier at the right is across an unknown band: not a way.
  auto rows = room(60, 20, 60);
  for (int j = 1; j < 19; ++j) {
    for (int i = 28; i < 32; ++i) rows[j][i] = '?';
  }
  const auto map = mapOf(rows);
  const auto frontiers = findFrontiers(*map, 3);
  ASSERT_EQ(frontiers.size(), 2u);  // both sides of the band
  const geometry::ClearanceMap known(map);
  const auto goal = nearestFrontier(known, {1.0, 1.0}, frontiers, options());
  ASSERT_TRUE(goal.has_value());
  EXPECT_LT(goal->goal.x, 2.8) << "the goal is on the robot's side of the unknown band";
}

}  // namespace
}  // namespace roomba_rrt::exploration
