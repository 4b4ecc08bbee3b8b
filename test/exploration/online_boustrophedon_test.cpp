// The classic Roomba's map and plan on hand-made maps (swept_map.h, online_boustrophedon.h): what
// is swept and blocked, how far it may drive, the boustrophedon's order, backtracking over swept
// floor only, never near a point found on an obstacle, and done when nothing is left.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "roomba_rrt/exploration/online_boustrophedon.h"
#include "roomba_rrt/exploration/swept_map.h"

namespace roomba_rrt::exploration {
namespace {

constexpr double kRadius = 0.17;
constexpr double kClearance = 0.01;

/// A robot's disc dragged from a to b: what driving there sweeps.
void sweepAlong(SweptMap& map, const geometry::Point2& a, const geometry::Point2& b) {
  const int n = static_cast<int>(std::ceil(geometry::distance(a, b) / 0.01)) + 1;
  for (int k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / n;
    map.sweep({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
  }
}

/// A wall of points every 2 cm from a to b.
std::vector<geometry::Point2> wall(SweptMap& map, const geometry::Point2& a,
                                   const geometry::Point2& b) {
  std::vector<geometry::Point2> points;
  const int n = static_cast<int>(std::ceil(geometry::distance(a, b) / 0.02));
  for (int k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / n;
    points.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    map.markObstacle(points.back());
  }
  return points;
}

/// Distance from p to the segment a-b.
double segmentDistance(const geometry::Point2& p, const geometry::Point2& a,
                       const geometry::Point2& b) {
  return geometry::distance(p, geometry::closestPoint(geometry::Segment{a, b}, p));
}

TEST(SweptMap, sweeps_exactly_the_cells_whose_centres_the_disc_holds) {
  SweptMap map({0, 0}, kRadius, kClearance);
  const geometry::Point2 c{0.3123, -0.2071};
  map.sweep(c);
  long inside = 0;
  for (int j = -40; j <= 40; ++j) {
    for (int i = -40; i <= 40; ++i) {
      const bool held = geometry::distance(map.centre({i, j}), c) <= kRadius;
      inside += held;
      EXPECT_EQ(map.swept({i, j}), held) << i << ", " << j;
      EXPECT_EQ(map.unknown({i, j}), !held);
    }
  }
  EXPECT_EQ(map.sweptCells(), inside);
}

TEST(SweptMap, blocks_every_centre_within_reach_of_a_point_and_grows_to_hold_it) {
  SweptMap map({0, 0}, kRadius, kClearance);
  const geometry::Point2 p{7.31, -4.02};  // beyond the first 2 m: the map grows
  map.markObstacle(p);
  EXPECT_TRUE(map.occupied(map.cellOf(p)));
  EXPECT_EQ(map.obstaclePoints(), 1u);
  map.markObstacle({p.x + 0.002, p.y});  // the same point again, seen by another scan
  EXPECT_EQ(map.obstaclePoints(), 1u);
  const Cell c = map.cellOf(p);
  for (int j = c.j - 12; j <= c.j + 12; ++j) {
    for (int i = c.i - 12; i <= c.i + 12; ++i) {
      EXPECT_EQ(map.blocked({i, j}), geometry::distance(map.centre({i, j}), p) <= map.reach())
          << i << ", " << j;
    }
  }
}

TEST(SweptMap, free_length_stops_the_disc_at_reach_of_the_first_point_ahead) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5), angle(-M_PI, M_PI);
  SweptMap map({0, 0}, kRadius, kClearance);
  std::vector<geometry::Point2> points;
  for (int k = 0; k < 60; ++k) {
    points.push_back({coordinate(rng), coordinate(rng)});
    map.markObstacle(points.back());
  }
  for (int trial = 0; trial < 300; ++trial) {
    const geometry::Point2 from{coordinate(rng), coordinate(rng)};
    const double a = angle(rng);
    const geometry::Point2 d{std::cos(a), std::sin(a)};
    const double length = map.freeLength(from, d, 1.0);
    // Brute force: the first centre, in steps of 0.1 mm, whose disc is within reach of a point
    // that lies ahead of it.
    double expected = 1.0;
    for (double t = 0; t <= 1.0; t += 1e-4) {
      const geometry::Point2 c{from.x + t * d.x, from.y + t * d.y};
      bool stop = false;
      for (const geometry::Point2& q : points) {
        const bool ahead = (q.x - c.x) * d.x + (q.y - c.y) * d.y > 0;
        stop = stop || (ahead && geometry::distance(c, q) < map.reach());
      }
      if (stop) {
        expected = std::max(0.0, t - 1e-4);
        break;
      }
    }
    EXPECT_NEAR(length, expected, 2e-4) << "trial " << trial;
  }
}

TEST(OnlineBoustrophedon, first_row_goes_the_way_the_robot_faces_then_shifts_then_comes_back) {
  SweptMap map({1, 1}, kRadius, kClearance);
  OnlineBoustrophedon plan({1, 1}, 0.0);
  map.sweep({1, 1});
  std::optional<Move> move = plan.next(map, {1, 1});
  ASSERT_TRUE(move);
  EXPECT_EQ(move->kind, Move::Kind::kRow);
  EXPECT_EQ(move->heading, Heading::kEast);
  EXPECT_TRUE(move->transit.empty());
  // The row driven to a wall 3 m on.
  sweepAlong(map, {1, 1}, {3.8, 1});
  wall(map, {4.0, 0}, {4.0, 4});
  move = plan.next(map, {3.8, 1});
  ASSERT_TRUE(move);
  EXPECT_EQ(move->kind, Move::Kind::kShift);
  EXPECT_EQ(move->heading, Heading::kNorth);
  EXPECT_NEAR(move->length, plan.options().swath, 1e-9);
  sweepAlong(map, {3.8, 1}, {3.8, 1 + plan.options().swath});
  move = plan.next(map, {3.8, 1 + plan.options().swath});
  ASSERT_TRUE(move);
  EXPECT_EQ(move->kind, Move::Kind::kRow);
  EXPECT_EQ(move->heading, Heading::kWest);
}

TEST(OnlineBoustrophedon, a_shift_is_stopped_short_by_a_wall_it_found) {
  SweptMap map({1, 1}, kRadius, kClearance);
  OnlineBoustrophedon plan({1, 1}, 0.0);
  sweepAlong(map, {1, 1}, {3, 1});
  // A wall 0.28 m above the row: a shift of 0.10 m at most.
  wall(map, {0, 1.28}, {5, 1.28});
  std::optional<Move> move = plan.next(map, {1, 1});  // the first row
  sweepAlong(map, {1, 1}, {3, 1});
  move = plan.next(map, {3, 1});
  ASSERT_TRUE(move);
  ASSERT_EQ(move->kind, Move::Kind::kShift);
  EXPECT_EQ(move->heading, Heading::kNorth);
  EXPECT_NEAR(map.freeLength({3, 1}, unit(Heading::kNorth), move->length), 0.1, 1e-6);
}

TEST(OnlineBoustrophedon, nothing_left_in_a_swept_room_walled_all_round_is_done) {
  SweptMap map({1, 1}, kRadius, kClearance);
  OnlineBoustrophedon plan({1, 1}, 0.0);
  // A 2 m x 1.3 m room: rows every 0.2 m sweep all of it, the walls found all round.
  for (double y = 0.17; y <= 1.13 + 1e-9; y += 0.16) sweepAlong(map, {0.17, y}, {1.83, y});
  wall(map, {0, 0}, {2, 0});
  wall(map, {2, 0}, {2, 1.3});
  wall(map, {2, 1.3}, {0, 1.3});
  wall(map, {0, 1.3}, {0, 0});
  EXPECT_FALSE(plan.next(map, {1, 0.65}));
}

TEST(OnlineBoustrophedon, backtracks_over_swept_floor_round_what_it_found_never_near_it) {
  SweptMap map({0.5, 0.5}, kRadius, kClearance);
  OnlineBoustrophedon plan({0.5, 0.5}, 0.0);
  // Rows swept in a U round a block found in the middle (1.2-2.8 x 0.9-2.1), open to the east:
  // unswept floor only east of the block, beyond the ends of the U's arms.
  for (int k = 0; k <= 7; ++k) {
    const double y = 0.5 + 0.3 * k;
    sweepAlong(map, {0.5, y}, {y < 0.9 || y > 2.1 ? 3.5 : 1.0, y});
  }
  sweepAlong(map, {0.5, 0.5}, {0.5, 2.6});
  std::vector<geometry::Point2> points = wall(map, {1.2, 0.9}, {2.8, 0.9});
  for (const auto& w : {wall(map, {2.8, 0.9}, {2.8, 2.1}), wall(map, {2.8, 2.1}, {1.2, 2.1}),
                        wall(map, {1.2, 2.1}, {1.2, 0.9})}) {
    points.insert(points.end(), w.begin(), w.end());
  }
  // Walls round the rest.
  for (const auto& w : {wall(map, {0.3, 0.3}, {3.7, 0.3}), wall(map, {0.3, 2.8}, {3.7, 2.8}),
                        wall(map, {0.3, 0.3}, {0.3, 2.8})}) {
    points.insert(points.end(), w.begin(), w.end());
  }
  const geometry::Point2 at{1.0, 1.4};  // in the U's west arm, the block between it and the rest
  std::optional<Move> move = plan.next(map, at);
  ASSERT_TRUE(move);
  ASSERT_GE(move->transit.size(), 2u) << "it must go round the block";
  EXPECT_GT(move->start.x, 2.9) << "to the floor east of the block";
  for (std::size_t k = 1; k < move->transit.size(); ++k) {
    for (const geometry::Point2& p : points) {
      ASSERT_GE(segmentDistance(p, move->transit[k - 1], move->transit[k]),
                map.reach() - map.resolution())
          << "transit leg " << k << " passes the point (" << p.x << ", " << p.y << ")";
    }
  }
  // And the move from there does not start near a point either.
  EXPECT_FALSE(map.blocked(map.cellOf(move->start)));
}

TEST(OnlineBoustrophedon, a_move_that_finds_nothing_is_not_tried_for_ever) {
  SweptMap map({1, 1}, kRadius, kClearance);
  OnlineBoustrophedon plan({1, 1}, 0.0);
  map.sweep({1, 1});
  // Whatever the robot reports, it never moves: each next() is tried, then given up.
  int moves = 0;
  while (plan.next(map, {1, 1})) ASSERT_LT(++moves, 10000);
  EXPECT_GE(moves, plan.options().max_tries);
  EXPECT_LE(moves, 200);
}

}  // namespace
}  // namespace roomba_rrt::exploration
