#include <gtest/gtest.h>

#include <cmath>

#include "planning_test_support.h"
#include "roomba_rrt/planning/lab/monte_carlo.h"
#include "roomba_rrt/planning/planners/rrt.h"

namespace roomba_rrt::planning {
namespace {

using testing::expectPathConnectsStartToGoal;
using testing::firstCollidingEdge;
using testing::labScenario;

TEST(Extend, a_sample_within_one_step_becomes_the_new_node) {
  const Point2 q = steer({1, 1}, {1.1, 1.1}, 0.2);
  EXPECT_EQ(q.x, 1.1);
  EXPECT_EQ(q.y, 1.1);
}

TEST(Extend, a_far_sample_gives_a_node_one_step_towards_it) {
  const Point2 q = steer({1, 1}, {4, 5}, 0.2);  // direction (0.6, 0.8)
  EXPECT_DOUBLE_EQ(q.x, 1.12);
  EXPECT_DOUBLE_EQ(q.y, 1.16);
  EXPECT_NEAR(distance(Point2{1, 1}, q), 0.2, 1e-15);
}

TEST(Rrt, goal_bias_one_in_an_empty_world_reaches_the_goal_in_ceil_dist_over_step_iterations) {
  Problem empty;
  empty.start = {1, 1};
  empty.goal = {9, 9};
  PlannerOptions options;
  options.goal_bias = 1.0;
  const PlanResult r = plan(empty, options);
  expectPathConnectsStartToGoal(r, empty, options.goal_tolerance);
  const int expected = static_cast<int>(std::ceil(distance(empty.start, empty.goal) / 0.2));
  EXPECT_EQ(r.iterations, expected);  // 57
  EXPECT_EQ(r.tree.size(), expected + 1);
  EXPECT_NEAR(r.length, distance(empty.start, empty.goal), 1e-9);
}

TEST(Rrt, solves_lab_scenario_a_with_a_path_from_start_to_goal) {
  const Problem a = labScenario("a");
  const PlanResult r = plan(a, PlannerOptions{});
  expectPathConnectsStartToGoal(r, a, 1e-3);
  EXPECT_EQ(r.tree.parent[0], -1);
  EXPECT_LE(r.iterations, 1000);
  EXPECT_GE(r.planning_time, 0.0);
}

TEST(Rrt, failure_returns_an_empty_path_and_infinite_length) {
  PlannerOptions options;
  options.max_iterations = 5;  // far too few for 11 m in steps of 0.2
  const PlanResult r = plan(labScenario("a"), options);
  EXPECT_FALSE(r.success);
  EXPECT_TRUE(r.path.empty());
  EXPECT_TRUE(std::isinf(r.length));
  EXPECT_GT(r.length, 0);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_FALSE(r.message.empty());
}

TEST(Rrt, one_seed_reproduces_the_same_tree) {
  PlannerOptions options;
  options.seed = 1234;
  const PlanResult first = plan(labScenario("c"), options);
  const PlanResult second = plan(labScenario("c"), options);
  ASSERT_EQ(first.tree.size(), second.tree.size());
  for (int i = 0; i < first.tree.size(); ++i) {
    ASSERT_EQ(first.tree.nodes[i].x, second.tree.nodes[i].x);
    ASSERT_EQ(first.tree.nodes[i].y, second.tree.nodes[i].y);
    ASSERT_EQ(first.tree.parent[i], second.tree.parent[i]);
  }
  options.seed = 1235;
  EXPECT_NE(plan(labScenario("c"), options).tree.nodes[1].x, first.tree.nodes[1].x);
}

TEST(Rrt, index_and_brute_force_grow_the_identical_tree) {
  PlannerOptions options;
  options.max_iterations = 3000;
  options.goal_tolerance = 0;  // never stop: a large tree
  const PlanResult indexed = plan(labScenario("d"), options);
  options.nearest = NearestSearch::kBruteForce;
  const PlanResult brute = plan(labScenario("d"), options);
  EXPECT_EQ(indexed.tree.parent, brute.tree.parent);
  EXPECT_GT(indexed.tree.size(), 2000);
}

TEST(Rrt, segments_mode_never_returns_a_path_with_an_edge_meeting_an_obstacle) {
  PlannerOptions options;
  options.collision = CollisionCheck::kSegments;
  for (const char* name : {"a", "b", "c", "d"}) {
    const Problem p = labScenario(name);
    for (std::uint32_t seed = 1; seed <= 30; ++seed) {
      options.seed = seed;
      const PlanResult r = plan(p, options);
      if (!r.success) continue;
      ASSERT_EQ(firstCollidingEdge(r.path, p.obstacles), -1) << name << " seed " << seed;
    }
  }
}

TEST(Rrt, points_mode_checks_only_nodes_so_an_edge_may_cut_an_obstacle) {
  // A thin wall between start and goal: with points only, one step jumps over it.
  Problem p;
  p.start = {4.95, 5};
  p.goal = {5.15, 5};
  p.obstacles = {{{5.05, 5}, 0.05}};
  PlannerOptions options;
  options.goal_bias = 1;
  const PlanResult jumped = plan(p, options);
  ASSERT_TRUE(jumped.success);
  EXPECT_EQ(firstCollidingEdge(jumped.path, p.obstacles), 0);
  options.collision = CollisionCheck::kSegments;
  EXPECT_FALSE(plan(p, options).success);
}

TEST(Rrt, a_world_without_free_room_fails_with_a_message_instead_of_hanging) {
  Problem p;
  p.start = {0, 0};
  p.goal = {10, 10};
  p.obstacles = {{{5, 5}, 7.0710}};  // leaves only slivers in the corners
  PlannerOptions options;
  options.goal_bias = 0;
  options.max_rejection_tries = 1000;
  const PlanResult r = plan(p, options);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("sampling"), std::string::npos) << r.message;
  EXPECT_TRUE(r.path.empty());
}

TEST(Rrt, progress_is_reported_every_n_iterations_with_the_growing_tree) {
  PlannerOptions options;
  options.max_iterations = 100;
  options.goal_tolerance = 0;
  std::vector<int> seen;
  plan(
      labScenario("a"), options,
      [&](const Tree& t, int it) {
        EXPECT_GE(t.size(), 1);
        seen.push_back(it);
      },
      25);
  EXPECT_EQ(seen, (std::vector<int>{25, 50, 75, 100}));
}

TEST(MonteCarlo, failures_count_the_maximum_iterations_and_have_no_length) {
  PlannerOptions options;
  options.max_iterations = 10;
  const MonteCarloStats s = runMonteCarlo(labScenario("a"), options, 20, 42);
  EXPECT_EQ(s.solved, 0);
  EXPECT_EQ(s.success_pct, 0);
  EXPECT_EQ(s.mean_iterations, 10);
  EXPECT_EQ(s.std_iterations, 0);
  EXPECT_TRUE(std::isnan(s.mean_length));
}

TEST(MonteCarlo, runs_continue_one_stream_seeded_once) {
  PlannerOptions options;
  const MonteCarloStats s = runMonteCarlo(labScenario("a"), options, 3, 42);
  MatlabRandom stream(42);
  double lengths = 0;
  for (int run = 0; run < 3; ++run) lengths += plan(labScenario("a"), options, stream).length;
  EXPECT_EQ(s.solved, 3);
  EXPECT_DOUBLE_EQ(s.mean_length, lengths / 3);
  EXPECT_EQ(runMonteCarlo(labScenario("a"), options, 3, 42).mean_length, s.mean_length);
}

}  // namespace
}  // namespace roomba_rrt::planning
