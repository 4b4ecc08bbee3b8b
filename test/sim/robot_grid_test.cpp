#include "roomba_rrt/sim/robot_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

using roomba_rrt::sim::RobotGrid;

TEST(RobotGrid, finds_every_robot_within_reach_after_random_moves_as_brute_force_does) {
  const double width = 6.4, height = 4.8, reach = 0.34;
  const int n = 200;
  RobotGrid grid(width, height, reach, n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-0.5, width + 0.5), y(-0.5, height + 0.5);
  std::vector<double> xs(n), ys(n);
  for (int i = 0; i < n; ++i) {
    xs[i] = x(rng);
    ys[i] = y(rng);
    grid.insert(i, xs[i], ys[i]);
  }
  for (int round = 0; round < 2000; ++round) {
    const int moved = static_cast<int>(rng() % n);
    xs[moved] = x(rng);
    ys[moved] = y(rng);
    grid.move(moved, xs[moved], ys[moved]);
    const double qx = x(rng), qy = y(rng);
    std::set<int> visited;
    grid.forEachNear(qx, qy, [&](int j) { EXPECT_TRUE(visited.insert(j).second) << "twice"; });
    for (int j = 0; j < n; ++j) {
      if (std::hypot(xs[j] - qx, ys[j] - qy) <= reach) {
        ASSERT_TRUE(visited.count(j)) << "robot " << j << " missed in round " << round;
      }
    }
    EXPECT_LT(visited.size(), static_cast<std::size_t>(n) / 4);  // not all of them
  }
}
