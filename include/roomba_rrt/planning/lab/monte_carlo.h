// The lab's monteCarloRRT: many runs of one scenario from one seeded stream, and statistics.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "roomba_rrt/planning/planner_options.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::planning {

/// The lab's five numbers (std with N - 1; NaN when undefined, e.g. no solved run).
struct MonteCarloStats {
  int runs = 0;
  int solved = 0;
  double success_pct = 0;
  double mean_length = 0;      ///< over solved runs
  double std_length = 0;       ///< over solved runs
  double mean_iterations = 0;  ///< over all runs; a failure counts max_iterations
  double std_iterations = 0;
  double seconds = 0;  ///< wall-clock time of all runs
};

/// rng(seed) once, then `runs` plans in sequence from that stream (options.seed is ignored;
/// options.random_stream kFast: the fast stream seeded once instead).
/// `on_run(done)` is called after each run (progress bars).
MonteCarloStats runMonteCarlo(const Problem& problem, const PlannerOptions& options, int runs,
                              std::uint32_t seed, const std::function<void(int)>& on_run = {});

}  // namespace roomba_rrt::planning
