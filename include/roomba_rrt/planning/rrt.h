// The lab's RRT.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/free_space_sampler.h"
#include "roomba_rrt/planning/matlab_random.h"
#include "roomba_rrt/planning/nearest_neighbors.h"
#include "roomba_rrt/planning/plan_result.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// Called with the tree and the iteration number, every `every` iterations (0 = never).
struct ProgressCallback {
  std::function<void(const Tree&, int)> call;
  int every = 0;
  void operator()(const Tree& tree, int iteration) const {
    if (call && every > 0 && iteration % every == 0) call(tree, iteration);
  }
};

/// The extend rule: q_rand itself when it is within `step` of q_near, otherwise the point at
/// distance `step` from q_near towards q_rand.
Point2 steer(const Point2& q_near, const Point2& q_rand, double step);

/// The collaborators every planner is handed, so each can be swapped without touching a loop.
struct PlannerParts {
  MatlabRandom& random;
  const FreeSpaceSampler& sampler;
  NearestNeighbors& nearest;
  const CollisionChecker& checker;
};

/// Makes `tree` a single root node at `root` and `nearest` an index of it over `bounds`.
void plantTree(Tree& tree, NearestNeighbors& nearest, const Point2& root, const Bounds& bounds);

/// Step 1 of an iteration: one rand() for the goal bias (the goal when r < p), otherwise a
/// free-space sample (x, then y, per rejection try). std::nullopt when no free point was found.
std::optional<Point2> sampleTarget(const Problem& problem, const PlannerOptions& options,
                                   const PlannerParts& parts);

/// Steps 2-5 (LaValle's EXTEND): nearest node to `target`, steer by at most `step`, check the
/// motion, insert the new node into `tree` and `nearest`. Returns its index, or -1 if blocked
/// or if the step has length zero (the target is already a tree node).
int extendTree(Tree& tree, NearestNeighbors& nearest, const CollisionChecker& checker,
               const Point2& target, double step);

/// The message of a run that found no free point to sample.
std::string noFreeSpaceMessage(const FreeSpaceSampler& sampler);

/// Grows a tree from problem.start: sample, extend, and stop when the new node is closer than
/// goal_tolerance to the goal. Ignores options.algorithm and options.smooth (see plan()).
PlanResult solveRrt(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                    const ProgressCallback& progress = {});

}  // namespace roomba_rrt::planning
