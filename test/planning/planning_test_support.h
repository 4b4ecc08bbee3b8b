// Helpers shared by the planning unit tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "roomba_rrt/planning/planner.h"

namespace roomba_rrt::planning::testing {

/// A lab scenario from config/rrt_scenarios.yaml.
inline Problem labScenario(const std::string& name) {
  return loadScenarios(ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml").at(name);
}

/// The message of the util::InvalidInput that validate() throws for the query; "" when it can be
/// planned.
inline std::string validationError(const Problem& problem, const PlannerOptions& options,
                                   int max_iterations_cap = kDefaultMaxIterationsCap) {
  try {
    validate(problem, options, max_iterations_cap);
    return "";
  } catch (const util::InvalidInput& invalid) {
    return invalid.what();
  }
}

/// Index of the first path edge that meets an obstacle, -1 if none.
inline int firstCollidingEdge(const std::vector<Point2>& path,
                              const std::vector<Circle>& obstacles) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    for (const Circle& c : obstacles) {
      if (segmentMeets({path[i - 1], path[i]}, c)) return static_cast<int>(i - 1);
    }
  }
  return -1;
}

/// A path that starts at the start, ends within `tolerance` of the goal, and whose length is
/// the sum of its segments.
inline void expectPathConnectsStartToGoal(const PlanResult& r, const Problem& p, double tolerance) {
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_GE(r.path.size(), 2u);
  EXPECT_DOUBLE_EQ(r.path.front().x, p.start.x);
  EXPECT_DOUBLE_EQ(r.path.front().y, p.start.y);
  EXPECT_LT(distance(r.path.back(), p.goal), tolerance);
  EXPECT_DOUBLE_EQ(r.length, pathLength(r.path));
}

}  // namespace roomba_rrt::planning::testing
