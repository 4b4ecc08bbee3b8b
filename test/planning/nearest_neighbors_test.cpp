#include <gtest/gtest.h>

#include <algorithm>

#include "roomba_rrt/planning/lab/matlab_random.h"
#include "roomba_rrt/planning/nearest_neighbors/brute_force_nearest_neighbors.h"
#include "roomba_rrt/planning/nearest_neighbors/grid_nearest_neighbors.h"

namespace roomba_rrt::planning {
namespace {

const Bounds kLab;  // [0, 10] x [0, 10]

Point2 uniformIn(const Bounds& b, MatlabRandom& random) {
  const double x = random.uniform(b.x_min, b.x_max);
  return {x, random.uniform(b.y_min, b.y_max)};
}

// The grid under test and the lab's brute force, holding the same points.
struct GridAndReference {
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  std::vector<Point2> positions;  // as a tree's node array

  explicit GridAndReference(const Bounds& bounds) {
    grid.clear(bounds, positions);
    brute.clear(bounds, positions);
  }
  void add(const Point2& p) {
    const int index = static_cast<int>(positions.size());
    positions.push_back(p);
    grid.add(p, index);
    brute.add(p, index);
  }
  // Uniform points, a dense cluster (as near an RRT's root) and exact duplicates (ties must go
  // to the lowest index, as MATLAB's min does).
  void fillLikeATree(int n, MatlabRandom& random) {
    for (int i = 0; i < n; ++i) {
      Point2 p = uniformIn(kLab, random);
      if (i % 3 == 0) p = {1 + 0.01 * random.uniform(), 1 + 0.01 * random.uniform()};
      if (i % 97 == 0 && i > 0) p = {5, 5};
      add(p);
    }
  }
};

TEST(NearestNeighbors, index_returns_the_brute_force_node_on_100000_random_queries) {
  MatlabRandom random(7);
  GridAndReference nn(kLab);
  nn.fillLikeATree(3000, random);
  for (int q = 0; q < 100000; ++q) {
    // Mostly inside the bounds, some on and beyond the border.
    const Point2 query = uniformIn({-0.5, 10.5, -0.5, 10.5}, random);
    ASSERT_EQ(nn.grid.nearest(query), nn.brute.nearest(query)) << "query " << q;
  }
  EXPECT_EQ(nn.grid.nearest({5, 5}), 97);  // the lowest of the duplicates
}

TEST(NearestNeighbors, small_trees_scanned_linearly_give_the_brute_force_node_and_lowest_tie) {
  // Below 512 points the index scans arrays four points at a time; every size 1..300 (so every
  // remainder of the padding), duplicates included.
  MatlabRandom random(5);
  GridAndReference nn(kLab);
  for (int i = 0; i < 300; ++i) {
    nn.add(i % 7 == 3 ? Point2{2, 2} : uniformIn(kLab, random));
    for (int q = 0; q < 20; ++q) {
      const Point2 query = q == 0 ? Point2{2, 2} : uniformIn(kLab, random);
      ASSERT_EQ(nn.grid.nearest(query), nn.brute.nearest(query)) << "size " << i + 1;
    }
  }
  EXPECT_EQ(nn.grid.nearest({2, 2}), 3);
}

TEST(NearestNeighbors, small_tree_with_indices_out_of_order_still_breaks_ties_by_index) {
  std::vector<Point2> positions(10);
  positions[9] = {1, 1};
  positions[5] = positions[1] = {4, 4};
  positions[2] = {3, 3};
  GridNearestNeighbors grid;
  grid.clear(kLab, positions);
  grid.add({1, 1}, 9);
  grid.add({4, 4}, 5);
  grid.add({3, 3}, 2);
  grid.add({4, 4}, 1);  // the same point as index 5, lower index
  EXPECT_EQ(grid.nearest({4.1, 4.1}), 1);
  EXPECT_EQ(grid.nearest({0, 0}), 9);
}

TEST(NearestNeighbors, index_answers_right_while_growing_through_resizes) {
  MatlabRandom random(11);
  GridAndReference nn(kLab);
  for (int i = 0; i < 5000; ++i) {
    nn.add(uniformIn(kLab, random));
    const Point2 query = uniformIn(kLab, random);
    ASSERT_EQ(nn.grid.nearest(query), nn.brute.nearest(query)) << "after " << i + 1 << " points";
  }
  EXPECT_EQ(nn.grid.size(), 5000);
  EXPECT_GT(nn.grid.cellCount(), 5000 / 4);  // it re-sized as it filled (at 4 points per cell)
}

TEST(NearestNeighbors, radius_query_finds_the_same_nodes_as_brute_force) {
  MatlabRandom random(3);
  std::vector<int> from_grid, from_brute;
  for (int n : {300, 2000}) {  // linear scan (no grid yet) and grid
    GridAndReference nn(kLab);
    nn.fillLikeATree(n, random);
    for (int q = 0; q < 1000; ++q) {
      const Point2 query = uniformIn(kLab, random);
      const double radius = random.uniform(0, 2);
      nn.grid.withinRadius(query, radius, from_grid);
      nn.brute.withinRadius(query, radius, from_brute);
      std::sort(from_grid.begin(), from_grid.end());
      std::sort(from_brute.begin(), from_brute.end());
      ASSERT_EQ(from_grid, from_brute) << n << " points";
    }
  }
}

TEST(NearestNeighbors, index_is_exact_for_queries_far_from_every_point) {
  // A tree that has not crossed scenario d's wall: points above y = 6, queries below y = 4.
  MatlabRandom random(13);
  GridAndReference nn(kLab);
  for (int i = 0; i < 20000; ++i) nn.add(uniformIn({0, 10, 6, 10}, random));
  for (int q = 0; q < 20000; ++q) {
    const Point2 query = uniformIn({0, 10, 0, 4}, random);
    ASSERT_EQ(nn.grid.nearest(query), nn.brute.nearest(query)) << "query " << q;
  }
}

TEST(NearestNeighbors, index_stays_small_and_exact_in_very_thin_bounds) {
  const Bounds thin{0, 1e6, 0, 1e-3};
  MatlabRandom random(5);
  GridAndReference nn(thin);
  for (int i = 0; i < 1000; ++i) nn.add(uniformIn(thin, random));
  EXPECT_LE(nn.grid.cellCount(), 2048);
  for (int q = 0; q < 1000; ++q) {
    const Point2 query = uniformIn(thin, random);
    ASSERT_EQ(nn.grid.nearest(query), nn.brute.nearest(query));
  }
}

TEST(NearestNeighbors, empty_structures_have_no_nearest_node) {
  GridAndReference nn(kLab);
  EXPECT_EQ(nn.grid.nearest({1, 1}), -1);
  EXPECT_EQ(nn.brute.nearest({1, 1}), -1);
}

}  // namespace
}  // namespace roomba_rrt::planning
