// Which legs the robot drives as one path (joined_legs.h): a U-turn, the way round an island and
// the loop along the walls are; a long transit, a row along a wall and a touch-up's turn back are
// not. In the lab's empty room, whose middle leaves the arcs room to round every corner.
#include "roomba_rrt/coverage/joined_legs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"

namespace roomba_rrt::coverage {
namespace {

Leg row(Point2 from, Point2 to, bool along_wall = false) {
  return Leg{Leg::Kind::kRow, {from, to}, along_wall};
}
Leg transit(Polyline points) { return Leg{Leg::Kind::kTransit, std::move(points), false}; }

/// True when `a` and `b` are the same points (a leg driven as planned: not rounded).
bool samePoints(const Polyline& a, const Polyline& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  }
  return true;
}

class JoinedLegsTest : public ::testing::Test {
 protected:
  JoinedLegsTest()
      : space_(world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml"), 0.01, 0.025) {}

  JoinedLegs join(const std::vector<Leg>& legs, std::size_t first, bool touching_up = false) {
    return joinLegs(legs, first, touching_up, space_);
  }

  /// The point of `path` at arc length `s`.
  static Point2 at(const Polyline& path, double s) {
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const double d = std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
      if (s <= d && d > 0) {
        return {path[i].x + (path[i + 1].x - path[i].x) * s / d,
                path[i].y + (path[i + 1].y - path[i].y) * s / d};
      }
      s -= d;
    }
    return path.back();
  }

  FreeSpace space_;
};

/// Two rows 0.33 m apart, joined by the step at their right ends: a U-turn.
std::vector<Leg> uTurn() {
  return {row({1, 1}, {5, 1}), transit({{5, 1}, {5, 1.33}}), row({5, 1.33}, {1, 1.33})};
}

TEST_F(JoinedLegsTest, a_u_turn_is_one_path_with_its_corners_rounded) {
  const std::vector<Leg> legs = uTurn();
  const JoinedLegs joined = join(legs, 0);
  EXPECT_TRUE(joined.cleaning);
  ASSERT_EQ(joined.ends.size(), 2u);  // the step, then the second row
  EXPECT_EQ(joined.path.front().x, 1);
  EXPECT_EQ(joined.path.back().x, 1);
  EXPECT_NEAR(joined.path.back().y, 1.33, 1e-12);
  // The two corners are arcs: no point of the path reaches the corner at (5, 1) or (5, 1.33).
  for (const Point2& p : joined.path) {
    EXPECT_GT(std::hypot(p.x - 5, p.y - 1), 0.03);
    EXPECT_GT(std::hypot(p.x - 5, p.y - 1.33), 0.03);
  }
  // Each joined leg starts where the path passes its first point (a rounded corner: mid-arc),
  // in order, and the path is shorter than the legs by what the arcs cut.
  const double length = geometry::pathLength(joined.path);
  EXPECT_LT(joined.ends[0], joined.ends[1]);
  EXPECT_LT(joined.ends[1], length);
  EXPECT_LT(length, 8.33);
  EXPECT_GT(length, 8.0);
  const Point2 step = at(joined.path, joined.ends[0]), second = at(joined.path, joined.ends[1]);
  EXPECT_LT(std::hypot(step.x - 5, step.y - 1), 0.1);
  EXPECT_LT(std::hypot(second.x - 5, second.y - 1.33), 0.1);
}

TEST_F(JoinedLegsTest, a_step_driven_from_its_start_takes_the_row_it_leads_to) {
  const std::vector<Leg> legs = uTurn();
  const JoinedLegs joined = join(legs, 1);
  EXPECT_TRUE(joined.cleaning);  // at the cleaning speed: it is part of a U-turn
  ASSERT_EQ(joined.ends.size(), 1u);
  EXPECT_EQ(joined.path.back().x, 1);
}

TEST_F(JoinedLegsTest, a_long_transit_is_driven_on_its_own_at_the_transit_speed) {
  const std::vector<Leg> legs = {row({1, 1}, {5, 1}), transit({{5, 1}, {5, 2}, {1, 2}}),
                                 row({1, 2}, {5, 2})};
  const JoinedLegs from_row = join(legs, 0);
  EXPECT_TRUE(from_row.cleaning);
  EXPECT_TRUE(from_row.ends.empty());
  EXPECT_TRUE(
      samePoints(from_row.path, legs[0].points));  // not rounded: the robot stops at its end

  const JoinedLegs from_transit = join(legs, 1);
  EXPECT_FALSE(from_transit.cleaning);
  EXPECT_TRUE(from_transit.ends.empty());
  EXPECT_TRUE(samePoints(from_transit.path, legs[1].points));
}

TEST_F(JoinedLegsTest, a_row_along_a_wall_is_never_joined) {
  std::vector<Leg> legs = uTurn();
  legs[2].along_wall = true;  // its own guard: the legs round it are driven apart
  const JoinedLegs joined = join(legs, 0);
  EXPECT_TRUE(joined.ends.empty());
  EXPECT_TRUE(samePoints(joined.path, legs[0].points));
}

TEST_F(JoinedLegsTest, a_touch_up_joins_only_where_the_path_turns_gently) {
  // Two stops on one line, the second behind the first: the step back turns by π.
  const std::vector<Leg> back = {row({3, 2}, {4, 2}), transit({{4, 2}, {3.8, 2}}),
                                 row({3.8, 2}, {2.5, 2})};
  EXPECT_TRUE(join(back, 0, /*touching_up=*/true).ends.empty());
  EXPECT_EQ(join(back, 0, /*touching_up=*/false).ends.size(), 2u);  // the rows' U-turn rule
  // Two stops on one line, the second ahead: joined in the touch-up too.
  const std::vector<Leg> ahead = {row({3, 2}, {4, 2}), transit({{4, 2}, {4.2, 2}}),
                                  row({4.2, 2}, {5, 2})};
  EXPECT_EQ(join(ahead, 0, /*touching_up=*/true).ends.size(), 2u);
}

TEST_F(JoinedLegsTest, the_way_round_an_island_joins_two_pieces_of_a_row) {
  // A row cut by an island between x = 2.5 and 3.5, the way round it 0.4 m above.
  const Polyline round = {{2.3, 2}, {2.5, 2.4}, {3.5, 2.4}, {3.7, 2}};
  const std::vector<Leg> legs = {row({1, 2}, {2.3, 2}), transit(round), row({3.7, 2}, {5, 2})};
  ASSERT_LE(geometry::pathLength(round), JoinRules::kDetour);
  const JoinedLegs joined = join(legs, 0);
  EXPECT_EQ(joined.ends.size(), 2u);
  EXPECT_EQ(joined.path.back().x, 5);

  // Not when the next piece leaves the row's line (a transit to another row: stop and turn).
  std::vector<Leg> off_line = legs;
  off_line[2] = row({3.7, 2.1}, {5, 2.1});
  off_line[1].points.back() = {3.7, 2.1};
  EXPECT_TRUE(join(off_line, 0).ends.empty());
  // Nor when the way round is longer than JoinRules::kDetour.
  std::vector<Leg> far = legs;
  far[1].points = {{2.3, 2}, {2.3, 3.2}, {3.7, 3.2}, {3.7, 2}};
  EXPECT_TRUE(join(far, 0).ends.empty());
}

TEST_F(JoinedLegsTest, the_loop_along_the_walls_is_driven_without_stopping) {
  // Segments of a loop are rows, each starting where the one before ended.
  const std::vector<Leg> legs = {row({1, 1}, {5, 1}), row({5, 1}, {5, 3}), row({5, 3}, {1, 3}),
                                 row({1, 3}, {1, 1.2})};
  const JoinedLegs joined = join(legs, 0);
  EXPECT_EQ(joined.ends.size(), 3u);
  EXPECT_NEAR(joined.path.back().y, 1.2, 1e-12);
  // From the second segment on: the rest of the loop.
  EXPECT_EQ(join(legs, 1).ends.size(), 2u);
  // A segment that turns back (sharper than JoinRules::kMaxTurn) ends the path.
  const std::vector<Leg> reversing = {row({1, 1}, {5, 1}), row({5, 1}, {2, 1.1})};
  EXPECT_TRUE(join(reversing, 0).ends.empty());
}

}  // namespace
}  // namespace roomba_rrt::coverage
