// The lab's RRT.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/free_space_sampler.h"
#include "roomba_rrt/planning/nearest_neighbors/nearest_neighbors.h"
#include "roomba_rrt/planning/plan_random.h"
#include "roomba_rrt/planning/plan_result.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/planning/stop_condition.h"

namespace roomba_rrt::planning {

/// Called with the tree and the iteration number, every `every` iterations (0 = never).
struct ProgressCallback {
  std::function<void(const Tree&, int)> call;
  int every = 0;
  void operator()(const Tree& tree, int iteration) const {
    if (call && every > 0 && iteration % every == 0) call(tree, iteration);
  }
};

/// steer() for points so far apart that their squared distance overflows (far beyond the ranges
/// validate() accepts): the same point, computed without overflow; never NaN for finite input.
Point2 steerFar(const Point2& q_near, const Point2& q_rand, double step);

/// The extend rule: q_rand itself when it is within `step` of q_near, otherwise the point at
/// distance `step` from q_near towards q_rand.
inline Point2 steer(const Point2& q_near, const Point2& q_rand, double step) {
  const double d = distance(q_near, q_rand);
  if (d <= step) return q_rand;
  // An overflowed distance would make the formula below inf / inf = NaN.
  if (!(d < std::numeric_limits<double>::infinity())) return steerFar(q_near, q_rand, step);
  // q_near + step * (q_rand - q_near) / d, evaluated in the lab's order.
  return {q_near.x + step * (q_rand.x - q_near.x) / d, q_near.y + step * (q_rand.y - q_near.y) / d};
}

/// The collaborators every planner is handed, so each can be swapped without touching a loop.
struct PlannerParts {
  PlanRandom& random;
  const FreeSpaceSampler& sampler;
  NearestNeighbors& nearest;
  const CollisionChecker& checker;
  /// Asked once per loop (extension step); nullptr: stop only after max_iterations.
  StopCondition* stop = nullptr;
};

/// Makes `tree` a single root node at `root` and `nearest` an index of it over `bounds`.
void plantTree(Tree& tree, NearestNeighbors& nearest, const Point2& root, const Bounds& bounds);

// steer, sampleTarget, steerFromNearest and extendTree are inline: they run every iteration, and
// a shared library cannot inline calls to its own exported functions.

/// Step 1 of an iteration: one rand() for the goal bias (the goal when r < p), otherwise a
/// free-space sample (x, then y, per rejection try). std::nullopt when no free point was found.
inline std::optional<Point2> sampleTarget(const Problem& problem, const PlannerOptions& options,
                                          const PlannerParts& parts) {
  if (parts.random.uniform() < options.goal_bias) return problem.goal;
  return parts.sampler.sample(parts.random);
}

/// A free motion of at most one step from tree node `from` (at `q_from`) to `q_new`.
struct Extension {
  int from;
  Point2 q_from;
  Point2 q_new;
};

/// Steps 2-4 of an iteration (LaValle's EXTEND without the insertion): the nearest node to
/// `target`, one step of at most `step` from it towards `target`, and the collision check of that
/// motion. std::nullopt if it is blocked, or if the step has length zero (the target is already
/// a tree node). `Index` is NearestNeighbors, or a concrete index whose calls the compiler can
/// then inline.
template <typename Index>
std::optional<Extension> steerFromNearest(const Index& nearest, const CollisionChecker& checker,
                                          const Point2& target, double step) {
  // Nearest tree node.
  const auto [near, q_near] = nearest.nearestNeighbor(target);
  // Extend from it by at most one step.
  const Point2 q_new = steer(q_near, target, step);
  // Check the new node (points) or the new edge (segments); a collision wastes the iteration.
  // A step of length zero (the target is already a node, e.g. the goal with epsilon = 0) adds
  // nothing either; it never happens in the lab's runs, which stop at the goal.
  if (!checker.isMotionFree(q_near, q_new)) return std::nullopt;
  if (q_new.x == q_near.x && q_new.y == q_near.y) return std::nullopt;
  return Extension{near, q_near, q_new};
}

/// Steps 2-5 (LaValle's EXTEND): steerFromNearest(), then insert the new node into `tree` and
/// `nearest` with the nearest node as its parent. Returns its index, or -1 if nothing was added.
template <typename Index>
int extendTree(Tree& tree, Index& nearest, const CollisionChecker& checker, const Point2& target,
               double step) {
  const std::optional<Extension> motion = steerFromNearest(nearest, checker, target, step);
  if (!motion) return -1;
  const int added = tree.add(motion->q_new, motion->from);
  nearest.add(motion->q_new, added);
  return added;
}

/// How many nodes a run of `max_iterations` can hold at most (the root and one per iteration),
/// capped at 2^22; planners reserve their tree arrays with it, so they are not copied as they grow.
std::size_t nodeCapacity(int max_iterations);

/// The message of a run that found no free point to sample.
std::string noFreeSpaceMessage(const FreeSpaceSampler& sampler);

/// Grows a tree from problem.start: sample, extend, and stop when the new node is closer than
/// goal_tolerance to the goal. Ignores options.algorithm and options.smooth (see plan()).
PlanResult solveRrt(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                    const ProgressCallback& progress = {});

}  // namespace roomba_rrt::planning
