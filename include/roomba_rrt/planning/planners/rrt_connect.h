// RRT-Connect (Kuffner & LaValle 2000): a tree from the start and one from the goal.
#pragma once

#include "roomba_rrt/planning/planners/rrt.h"

namespace roomba_rrt::planning {

/// Per iteration: sample (goal bias is not used: the other tree is the bias), extend the active
/// tree one step towards the sample; if a node was added, extend the other tree repeatedly
/// towards that node until it reaches it (a path) or is blocked; then swap the trees' roles.
/// Every extension step, each connect step included, is one of the max_iterations (and the
/// result's `iterations` counts them), so a run adds at most max_iterations nodes.
/// `parts.nearest` indexes the start tree; the goal tree gets an index of the same kind.
/// The result's tree holds both trees (goal tree after the start tree, its root parent -1).
PlanResult solveRrtConnect(const Problem& problem, const PlannerOptions& options,
                           PlannerParts parts, const ProgressCallback& progress = {});

}  // namespace roomba_rrt::planning
