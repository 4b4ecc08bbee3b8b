// Input checks with messages that name the offending field.
#pragma once

#include "roomba_rrt/planning/limits.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::planning {

/// Throws util::InvalidInput naming the first field the query cannot be planned with, e.g.
/// "start: inside obstacle 0", "step: must be in [1e-06, 1e+06] m, got -1",
/// "obstacles[2].radius: must be in [0, 1e+06] m, got -1"; returns when it can be planned.
/// Checks: NaN/Inf anywhere; empty or inverted bounds, or a span beyond the double range; negative
/// radius; a rectangle with a NaN corner, or empty or inverted ("rectangles[2].max_x: must be >
/// min_x"); robot_radius or clearance NaN, negative, or too big for the bounds; start/goal outside
/// the bounds shrunk by robot_radius + clearance or inside an obstacle grown by it; step <= 0;
/// goal_bias outside [0, 1]; max_iterations < 1 or above `max_iterations_cap`; goal_tolerance < 0;
/// max_rejection_tries < 1; smoothing_tries < 0; the supported ranges of limits.h (coordinates,
/// bounds extent, step, goal_tolerance, radius, obstacle count, max_planning_time); and for
/// region_astar a map and no circles or rectangles ("algorithm: region_astar plans on a map ...",
/// "obstacles: region_astar plans on the map's cells alone ...").
void validate(const Problem& problem, const PlannerOptions& options,
              int max_iterations_cap = kDefaultMaxIterationsCap);

}  // namespace roomba_rrt::planning
