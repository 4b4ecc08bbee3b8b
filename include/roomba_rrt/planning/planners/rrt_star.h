// RRT* (Karaman & Frazzoli 2011): RRT that chooses the cheapest parent and rewires neighbours.
#pragma once

#include "roomba_rrt/planning/planners/rrt.h"

namespace roomba_rrt::planning {

/// Same sampling and steering as solveRrt, then: among the nodes within the shrinking radius
/// r = max(step, gamma * sqrt(ln n / n)) pick the parent giving the shortest path to the new node,
/// and re-parent neighbours that get shorter through it. It keeps improving for all
/// max_iterations and returns the shortest path to a node within goal_tolerance of the goal.
PlanResult solveRrtStar(const Problem& problem, const PlannerOptions& options, PlannerParts parts,
                        const ProgressCallback& progress = {});

}  // namespace roomba_rrt::planning
