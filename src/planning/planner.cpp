#include "roomba_rrt/planning/planner.h"

#include <chrono>

#include "roomba_rrt/planning/grid_regions.h"
#include "roomba_rrt/planning/path_smoothing.h"
#include "roomba_rrt/planning/planners/region_astar.h"
#include "roomba_rrt/planning/planners/rrt.h"
#include "roomba_rrt/planning/planners/rrt_connect.h"
#include "roomba_rrt/planning/planners/rrt_star.h"

namespace roomba_rrt::planning {

PlanResult plan(const Problem& problem, const PlannerOptions& options, PlanRandom& random,
                const std::function<void(const Tree&, int)>& on_progress, int progress_every,
                const std::function<bool()>& stop_requested) {
  const auto started = std::chrono::steady_clock::now();
  PlanResult result;
  try {
    validate(problem, options);
  } catch (const util::InvalidInput& invalid) {
    setNoPath(result, invalid.what());
    return result;
  }
  if (distance(problem.start, problem.goal) < options.goal_tolerance) {
    // Already there: the tree is its root, the path that one point.
    result.tree.add(problem.start, -1);
    setPathToNode(result, 0, "the start is within goal_tolerance of the goal");
    result.planning_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  }
  StopCondition stop(options.max_planning_time, stop_requested);
  if (options.algorithm == Algorithm::kRegionAStar) {
    // The map's regions for the robot's margin: the problem's, built once per map, or for this
    // plan alone when the problem carries none of this map.
    const double margin = robotMargin(problem);
    const std::shared_ptr<const GridRegions> regions =
        problem.regions && problem.regions->map() == problem.map
            ? problem.regions->get(margin)
            : std::make_shared<const GridRegions>(problem.map, margin);
    result = solveRegionAStar(*regions, problem.start, problem.goal, &stop);
    result.planning_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  }
  // A robot of some size plans in the grown world: obstacles grown by the margin (the checker),
  // walls moved in by it (the bounds the planners sample in). A point robot (the lab) plans in
  // the problem as given, without a copy.
  const double margin = robotMargin(problem);
  Problem shrunk;
  if (margin > 0) {
    shrunk = problem;
    shrunk.bounds = shrink(problem.bounds, margin);
  }
  const Problem& world = margin > 0 ? shrunk : problem;
  // The collaborators: collision checker, free-space sampler, nearest-neighbour structure.
  const CollisionChecker checker = collisionChecker(problem, options.collision);
  const FreeSpaceSampler sampler(world.bounds, checker, options.max_rejection_tries);
  const auto nearest = makeNearestNeighbors(options.nearest);
  const PlannerParts parts{random, sampler, *nearest, checker, &stop};
  const ProgressCallback progress{on_progress, progress_every};
  switch (options.algorithm) {
    case Algorithm::kRrt:
      result = solveRrt(world, options, parts, progress);
      break;
    case Algorithm::kRrtConnect:
      result = solveRrtConnect(world, options, parts, progress);
      break;
    case Algorithm::kRrtStar:
      result = solveRrtStar(world, options, parts, progress);
      break;
    case Algorithm::kRegionAStar:
      break;  // planned above
  }
  if (result.success && options.smooth) {
    result.path =
        shortcutPath(std::move(result.path), checker, options.smoothing_tries, options.seed);
    result.length = pathLength(result.path);
  }
  result.planning_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

PlanResult plan(const Problem& problem, const PlannerOptions& options,
                const std::function<void(const Tree&, int)>& on_progress, int progress_every,
                const std::function<bool()>& stop_requested) {
  PlanRandom random(options.seed, options.random_stream);
  return plan(problem, options, random, on_progress, progress_every, stop_requested);
}

PlanResult plan(const Problem& problem, const PlannerOptions& options, MatlabRandom& random,
                const std::function<void(const Tree&, int)>& on_progress, int progress_every,
                const std::function<bool()>& stop_requested) {
  PlanRandom continued(random);
  return plan(problem, options, continued, on_progress, progress_every, stop_requested);
}

}  // namespace roomba_rrt::planning
