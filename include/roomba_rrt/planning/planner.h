// The planning library's entry point: validate, plan, (smooth). Include this one header.
#pragma once

#include <functional>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/lab/matlab_random.h"
#include "roomba_rrt/planning/lab/scenarios.h"
#include "roomba_rrt/planning/limits.h"
#include "roomba_rrt/planning/plan_random.h"
#include "roomba_rrt/planning/plan_result.h"
#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"
#include "roomba_rrt/planning/stop_condition.h"
#include "roomba_rrt/planning/tree.h"
#include "roomba_rrt/planning/validate.h"

namespace roomba_rrt::planning {

/// Validates (failure with the message of validate()'s InvalidInput, nothing planned), then runs
/// options.algorithm with a fresh stream PlanRandom(options.seed, options.random_stream), the index
/// options.nearest and the collision mode options.collision, and smooths the path when
/// options.smooth is set. A start already within goal_tolerance of the goal is the one-point path
/// [start], length 0. Calls on_progress(tree, iteration) every progress_every iterations (rviz
/// animation). Stops early, with success false and StopCondition's message, once
/// options.max_planning_time has passed or `stop_requested()` returns true (asked every millisecond
/// or so; see StopCondition).
PlanResult plan(const Problem& problem, const PlannerOptions& options,
                const std::function<void(const Tree&, int)>& on_progress = {},
                int progress_every = 0, const std::function<bool()>& stop_requested = {});

/// The same, drawing from `random` (Monte Carlo: many runs from one stream, as MATLAB does);
/// options.seed and options.random_stream are not used for the plan's draws.
PlanResult plan(const Problem& problem, const PlannerOptions& options, PlanRandom& random,
                const std::function<void(const Tree&, int)>& on_progress = {},
                int progress_every = 0, const std::function<bool()>& stop_requested = {});
/// The same, continuing the MATLAB stream `random`.
PlanResult plan(const Problem& problem, const PlannerOptions& options, MatlabRandom& random,
                const std::function<void(const Tree&, int)>& on_progress = {},
                int progress_every = 0, const std::function<bool()>& stop_requested = {});

}  // namespace roomba_rrt::planning
