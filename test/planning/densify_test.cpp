#include "roomba_rrt/planning/densify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace roomba_rrt::planning {
namespace {

// The largest distance between consecutive points.
double widestGap(const std::vector<Point2>& path) {
  double widest = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    widest = std::max(widest, distance(path[i - 1], path[i]));
  }
  return widest;
}

// Whether every point of `sparse` is in `dense`, in order.
bool keepsVertices(const std::vector<Point2>& sparse, const std::vector<Point2>& dense) {
  std::size_t j = 0;
  for (const Point2& p : dense) {
    if (j < sparse.size() && p.x == sparse[j].x && p.y == sparse[j].y) ++j;
  }
  return j == sparse.size();
}

TEST(Densify, a_five_metre_edge_at_five_centimetres_gets_a_point_every_five_centimetres) {
  const std::vector<Point2> dense = densify({{0, 0}, {5, 0}}, 0.05);
  ASSERT_EQ(dense.size(), 101u);
  for (std::size_t i = 0; i < dense.size(); ++i) {
    EXPECT_NEAR(dense[i].x, 0.05 * i, 1e-12);
    EXPECT_EQ(dense[i].y, 0);
  }
}

TEST(Densify, every_vertex_is_kept_and_no_gap_is_wider_than_the_spacing) {
  const std::vector<Point2> path{{1, 1}, {1.33, 4.2}, {6.1, 4.25}, {6.1, 4.25}, {9, 9}};
  const std::vector<Point2> dense = densify(path, 0.1);
  EXPECT_TRUE(keepsVertices(path, dense));
  EXPECT_LE(widestGap(dense), 0.1);
  EXPECT_GT(widestGap(dense), 0.09);  // the pieces of an edge are equal: no needless points
  // Points lie on the polyline: its length is unchanged.
  double sparse_length = 0, dense_length = 0;
  for (std::size_t i = 1; i < path.size(); ++i) sparse_length += distance(path[i - 1], path[i]);
  for (std::size_t i = 1; i < dense.size(); ++i) dense_length += distance(dense[i - 1], dense[i]);
  EXPECT_NEAR(dense_length, sparse_length, 1e-9);
}

TEST(Densify, a_path_already_dense_enough_is_returned_as_it_is) {
  const std::vector<Point2> path{{0, 0}, {0.03, 0.04}, {0.06, 0.08}};
  const std::vector<Point2> dense = densify(path, 0.05);
  ASSERT_EQ(dense.size(), path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_EQ(dense[i].x, path[i].x);
    EXPECT_EQ(dense[i].y, path[i].y);
  }
}

TEST(Densify, empty_single_point_and_a_bad_spacing_give_the_path_unchanged) {
  EXPECT_TRUE(densify({}, 0.05).empty());
  EXPECT_EQ(densify({{2, 3}}, 0.05).size(), 1u);
  const std::vector<Point2> path{{0, 0}, {10, 0}};
  for (const double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    EXPECT_EQ(densify(path, bad).size(), 2u) << "spacing " << bad;
  }
}

TEST(Densify, a_spacing_that_would_give_too_many_points_is_widened_to_the_budget) {
  // 3 km at a micrometre would be 3e9 points: the budget holds, the vertices stay.
  const std::vector<Point2> path{{0, 0}, {1000, 0}, {1000, 2000}};
  const std::vector<Point2> dense = densify(path, 1e-6, 1000);
  EXPECT_LE(dense.size(), 1000u);
  EXPECT_GE(dense.size(), 990u);
  EXPECT_TRUE(keepsVertices(path, dense));
  EXPECT_LE(widestGap(dense), 3000.0 / 997 + 1e-9);
  // A budget no larger than the vertices: the path itself.
  EXPECT_EQ(densify(path, 1e-6, 3).size(), 3u);
}

}  // namespace
}  // namespace roomba_rrt::planning
