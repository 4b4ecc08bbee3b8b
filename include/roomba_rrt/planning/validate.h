// Input checks with messages that name the offending field.
#pragma once

#include <string>

#include "roomba_rrt/planning/limits.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// Returns "" when the query can be planned, otherwise one message naming the field, e.g.
/// "start: inside obstacle 0", "step: must be > 0 (got -1)", "obstacles[2].radius: negative".
/// Checks: NaN/Inf anywhere; empty or inverted bounds; start/goal outside the bounds or inside an
/// obstacle; goal_bias outside [0, 1]; max_iterations < 1 or above `max_iterations_cap`;
/// max_rejection_tries < 1; smoothing_tries < 0; and the supported ranges of limits.h (coordinates,
/// bounds extent, step, goal_tolerance, radius, obstacle count, max_planning_time).
std::string validate(const Problem& problem, const PlannerOptions& options,
                     int max_iterations_cap = kDefaultMaxIterationsCap);

}  // namespace roomba_rrt::planning
