#include <gtest/gtest.h>

#include <algorithm>

#include "roomba_rrt/planning/brute_force_nearest_neighbors.h"
#include "roomba_rrt/planning/grid_nearest_neighbors.h"
#include "roomba_rrt/planning/matlab_random.h"

namespace roomba_rrt::planning {
namespace {

const Bounds kLab;  // [0, 10] x [0, 10]

// Fills both structures with the same points: uniform ones, a dense cluster (as near an RRT's
// root), and exact duplicates (ties must go to the lowest index, as MATLAB's min does).
void fill(NearestNeighbors& a, NearestNeighbors& b, int n, MatlabRandom& random) {
  a.clear(kLab);
  b.clear(kLab);
  for (int i = 0; i < n; ++i) {
    Point2 p{random.uniform(0, 10), random.uniform(0, 10)};
    if (i % 3 == 0) p = {1 + 0.01 * random.uniform(), 1 + 0.01 * random.uniform()};
    if (i % 97 == 0 && i > 0) p = {5, 5};
    a.add(p, i);
    b.add(p, i);
  }
}

TEST(NearestNeighbors, index_returns_the_brute_force_node_on_100000_random_queries) {
  MatlabRandom random(7);
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  fill(grid, brute, 3000, random);
  for (int q = 0; q < 100000; ++q) {
    // Mostly inside the bounds, some on and beyond the border.
    const Point2 query{random.uniform(-0.5, 10.5), random.uniform(-0.5, 10.5)};
    ASSERT_EQ(grid.nearest(query), brute.nearest(query)) << "query " << q;
  }
  EXPECT_EQ(grid.nearest({5, 5}), 97);  // the lowest of the duplicates
}

TEST(NearestNeighbors, index_answers_right_while_growing_through_resizes) {
  MatlabRandom random(11);
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  grid.clear(kLab);
  brute.clear(kLab);
  for (int i = 0; i < 5000; ++i) {
    const Point2 p{random.uniform(0, 10), random.uniform(0, 10)};
    grid.add(p, i);
    brute.add(p, i);
    const Point2 query{random.uniform(0, 10), random.uniform(0, 10)};
    ASSERT_EQ(grid.nearest(query), brute.nearest(query)) << "after " << i + 1 << " points";
  }
  EXPECT_EQ(grid.size(), 5000);
  EXPECT_GT(grid.cellCount(), 5000 / 2);  // it re-sized as it filled
}

TEST(NearestNeighbors, radius_query_finds_the_same_nodes_as_brute_force) {
  MatlabRandom random(3);
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  fill(grid, brute, 2000, random);
  std::vector<int> from_grid, from_brute;
  for (int q = 0; q < 1000; ++q) {
    const Point2 query{random.uniform(0, 10), random.uniform(0, 10)};
    const double radius = random.uniform(0, 2);
    grid.withinRadius(query, radius, from_grid);
    brute.withinRadius(query, radius, from_brute);
    std::sort(from_grid.begin(), from_grid.end());
    std::sort(from_brute.begin(), from_brute.end());
    ASSERT_EQ(from_grid, from_brute);
  }
}

TEST(NearestNeighbors, index_is_exact_for_queries_far_from_every_point) {
  // A tree that has not crossed scenario d's wall: points above y = 6, queries below y = 4.
  MatlabRandom random(13);
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  grid.clear(kLab);
  brute.clear(kLab);
  for (int i = 0; i < 20000; ++i) {
    const Point2 p{random.uniform(0, 10), random.uniform(6, 10)};
    grid.add(p, i);
    brute.add(p, i);
  }
  for (int q = 0; q < 20000; ++q) {
    const Point2 query{random.uniform(0, 10), random.uniform(0, 4)};
    ASSERT_EQ(grid.nearest(query), brute.nearest(query)) << "query " << q;
  }
}

TEST(NearestNeighbors, index_stays_small_and_exact_in_very_thin_bounds) {
  const Bounds thin{0, 1e6, 0, 1e-3};
  MatlabRandom random(5);
  GridNearestNeighbors grid;
  BruteForceNearestNeighbors brute;
  grid.clear(thin);
  brute.clear(thin);
  for (int i = 0; i < 1000; ++i) {
    const Point2 p{random.uniform(0, 1e6), random.uniform(0, 1e-3)};
    grid.add(p, i);
    brute.add(p, i);
  }
  EXPECT_LE(grid.cellCount(), 2048);
  for (int q = 0; q < 1000; ++q) {
    const Point2 query{random.uniform(0, 1e6), random.uniform(0, 1e-3)};
    ASSERT_EQ(grid.nearest(query), brute.nearest(query));
  }
}

TEST(NearestNeighbors, empty_structures_have_no_nearest_node) {
  GridNearestNeighbors grid;
  grid.clear(kLab);
  EXPECT_EQ(grid.nearest({1, 1}), -1);
  BruteForceNearestNeighbors brute;
  EXPECT_EQ(brute.nearest({1, 1}), -1);
}

}  // namespace
}  // namespace roomba_rrt::planning
