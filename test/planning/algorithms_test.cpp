#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

#include "planning_test_support.h"
#include "roomba_rrt/planning/path_smoothing.h"

namespace roomba_rrt::planning {
namespace {

using testing::expectPathConnectsStartToGoal;
using testing::firstCollidingEdge;
using testing::labScenario;

class EveryScenario : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryScenario, rrt_connect_finds_a_collision_free_path_with_short_edges) {
  const Problem p = labScenario(GetParam());
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtConnect;
  options.collision = CollisionCheck::kSegments;
  options.max_iterations = 10000;  // scenario d's narrow gaps (0.15 m) take a while
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    options.seed = seed;
    const PlanResult r = plan(p, options);
    expectPathConnectsStartToGoal(r, p, 1e-9);  // ends exactly at the goal tree's root
    EXPECT_EQ(firstCollidingEdge(r.path, p.obstacles), -1);
    for (std::size_t i = 1; i < r.path.size(); ++i) {
      EXPECT_LE(distance(r.path[i - 1], r.path[i]), options.step + 1e-12);
    }
  }
}

TEST_P(EveryScenario, rrt_star_finds_a_collision_free_path) {
  const Problem p = labScenario(GetParam());
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtStar;
  options.collision = CollisionCheck::kSegments;
  options.max_iterations = 2000;
  const PlanResult r = plan(p, options);
  expectPathConnectsStartToGoal(r, p, options.goal_tolerance);
  EXPECT_EQ(firstCollidingEdge(r.path, p.obstacles), -1);
  EXPECT_EQ(r.iterations, options.max_iterations);  // RRT* keeps improving
}

TEST_P(EveryScenario, smoothing_never_lengthens_a_path_and_keeps_it_collision_free) {
  const Problem p = labScenario(GetParam());
  PlannerOptions options;
  options.collision = CollisionCheck::kSegments;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    options.seed = seed;
    options.smooth = false;
    const PlanResult raw = plan(p, options);
    if (!raw.success) continue;
    options.smooth = true;
    const PlanResult smooth = plan(p, options);
    expectPathConnectsStartToGoal(smooth, p, options.goal_tolerance);
    EXPECT_LE(smooth.length, raw.length + 1e-12);
    EXPECT_EQ(firstCollidingEdge(smooth.path, p.obstacles), -1);
    EXPECT_EQ(smooth.path.back().x, raw.path.back().x);
  }
}

INSTANTIATE_TEST_SUITE_P(LabScenarios, EveryScenario, ::testing::Values("a", "b", "c", "d"));

TEST(RrtStar, approaches_the_straight_line_in_an_empty_world) {
  Problem empty;
  empty.start = {1, 1};
  empty.goal = {9, 9};
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtStar;
  options.max_iterations = 3000;
  const PlanResult star = plan(empty, options);
  ASSERT_TRUE(star.success);
  const double straight = distance(empty.start, empty.goal);
  EXPECT_LT(star.length, 1.03 * straight);
}

TEST(EveryAlgorithm, paths_never_repeat_a_point) {
  // The reported case: RRT* returned a path whose last two poses were equal. A zero-length
  // segment must never appear, whatever the algorithm, seed or smoothing.
  Problem p;
  p.start = {1, 5};
  p.goal = {9, 5};
  p.obstacles = {{{5, 5}, 1.5}};
  p.bounds = {-1, 11, -1, 11};
  PlannerOptions options;
  options.collision = CollisionCheck::kSegments;
  options.max_iterations = 5000;
  for (Algorithm algorithm : {Algorithm::kRrt, Algorithm::kRrtConnect, Algorithm::kRrtStar}) {
    for (std::uint32_t seed = 40; seed < 60; ++seed) {
      for (bool smooth : {false, true}) {
        options.algorithm = algorithm;
        options.seed = seed;
        options.smooth = smooth;
        const PlanResult r = plan(p, options);
        ASSERT_TRUE(r.success) << r.message;
        for (std::size_t i = 1; i < r.path.size(); ++i) {
          ASSERT_GT(distance(r.path[i - 1], r.path[i]), 0.0)
              << "algorithm " << static_cast<int>(algorithm) << ", seed " << seed << ", smooth "
              << smooth << ": points " << i - 1 << " and " << i << " are equal";
        }
      }
    }
  }
}

TEST(RrtStar, rewiring_keeps_a_tree_every_node_reaches_the_start) {
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtStar;
  options.max_iterations = 1500;
  const PlanResult r = plan(labScenario("c"), options);
  ASSERT_TRUE(r.success);
  for (int i = 0; i < r.tree.size(); ++i) {
    int steps = 0;
    int node = i;
    while (r.tree.parent[node] >= 0 && steps <= r.tree.size()) {
      node = r.tree.parent[node];
      ++steps;
    }
    ASSERT_EQ(node, 0) << "node " << i << " does not lead to the start (cycle?)";
  }
}

TEST(Smoothing, is_reproducible_and_straightens_a_detour_in_an_empty_world) {
  const std::vector<Point2> zigzag{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  const CollisionChecker nothing({}, CollisionCheck::kSegments);
  const auto once = shortcutPath(zigzag, nothing, 50, 5);
  EXPECT_EQ(once.size(), 2u);  // free space: one straight segment remains
  const auto again = shortcutPath(zigzag, nothing, 50, 5);
  ASSERT_EQ(once.size(), again.size());
  EXPECT_EQ(once.back().x, 4);
}

TEST(RrtConnect, connects_even_with_zero_goal_tolerance) {
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtConnect;
  options.goal_tolerance = 0;
  const Problem a = labScenario("a");
  expectPathConnectsStartToGoal(plan(a, options), a, 1e-12);
}

TEST(RrtConnect, tree_holds_both_trees_each_with_its_root) {
  PlannerOptions options;
  options.algorithm = Algorithm::kRrtConnect;
  const PlanResult r = plan(labScenario("a"), options);
  ASSERT_TRUE(r.success);
  int roots = 0;
  for (int p : r.tree.parent) roots += p < 0;
  EXPECT_EQ(roots, 2);
}

// Every bit of a result: the path's and the tree's coordinates and the tree's parents (FNV-1a).
std::uint64_t fingerprint(const PlanResult& r) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](const void* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      h ^= static_cast<const unsigned char*>(data)[i];
      h *= 1099511628211ull;
    }
  };
  for (const Point2& p : r.path) {
    mix(&p.x, sizeof p.x);
    mix(&p.y, sizeof p.y);
  }
  for (int i = 0; i < r.tree.size(); ++i) {
    mix(&r.tree.nodes[i].x, sizeof(double));
    mix(&r.tree.nodes[i].y, sizeof(double));
    mix(&r.tree.parent[i], sizeof(int));
  }
  return h;
}

struct Recorded {
  const char* scenario;
  Algorithm algorithm;
  CollisionCheck collision;
  bool smooth;
  int iterations;
  int tree_size;
  double length;
  std::uint64_t fingerprint;
  const char* message;
};

// Recorded before the planners shared their extend step and result builder (seed 3, 1000
// iterations): a change that alters one draw, one node or one message shows here.
TEST(EveryAlgorithm, reproduces_the_recorded_runs_bit_for_bit) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Recorded runs[] = {
      {"a", Algorithm::kRrt, CollisionCheck::kPoints, false, 234, 224, 0x1.c159a1167016fp+3,
       0xeeec8f37bfbfabeaull, "path found"},
      {"a", Algorithm::kRrt, CollisionCheck::kSegments, true, 212, 199, 0x1.7844d3334030cp+3,
       0xd8323fba88dbedf3ull, "path found"},
      {"a", Algorithm::kRrtConnect, CollisionCheck::kSegments, false, 168, 102,
       0x1.afcb738c4ef43p+3, 0x7a603765edf1954eull, "path found"},
      {"a", Algorithm::kRrtStar, CollisionCheck::kSegments, false, 1000, 904, 0x1.70ef4146bd308p+3,
       0xcb5f910e5f0ea317ull, "path found (best of 1000 iterations)"},
      {"d", Algorithm::kRrt, CollisionCheck::kPoints, false, 1000, 500, kInf, 0x733f0d1d1961e58full,
       "no path within 1000 iterations"},
      {"d", Algorithm::kRrtConnect, CollisionCheck::kSegments, false, 754, 319,
       0x1.4e42d44f058d8p+4, 0xe6831e0c14ed3ffeull, "path found"},
      {"d", Algorithm::kRrtStar, CollisionCheck::kSegments, false, 1000, 500, kInf,
       0x39b34b1e87705c9eull, "no path within 1000 iterations"},
  };
  for (const Recorded& run : runs) {
    PlannerOptions options;
    options.algorithm = run.algorithm;
    options.collision = run.collision;
    options.smooth = run.smooth;
    options.seed = 3;
    const PlanResult r = plan(labScenario(run.scenario), options);
    const std::string what = std::string(run.scenario) + " " + toString(run.algorithm);
    EXPECT_EQ(r.iterations, run.iterations) << what;
    EXPECT_EQ(r.tree.size(), run.tree_size) << what;
    EXPECT_EQ(r.length, run.length) << what;
    EXPECT_EQ(fingerprint(r), run.fingerprint) << what;
    EXPECT_EQ(r.message, run.message) << what;
  }
}

}  // namespace
}  // namespace roomba_rrt::planning
