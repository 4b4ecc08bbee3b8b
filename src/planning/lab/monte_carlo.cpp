#include "roomba_rrt/planning/lab/monte_carlo.h"

#include <chrono>
#include <cmath>
#include <vector>

#include "roomba_rrt/planning/planner.h"
#include "roomba_rrt/util/statistics.h"

namespace roomba_rrt::planning {

MonteCarloStats runMonteCarlo(const Problem& problem, const PlannerOptions& options, int runs,
                              std::uint32_t seed, const std::function<void(int)>& on_run) {
  const auto started = std::chrono::steady_clock::now();
  // rng(seed) once (or the fast stream seeded once); every run continues the same stream.
  PlanRandom random(seed, options.random_stream);
  std::vector<double> lengths;
  std::vector<double> iterations;
  for (int run = 0; run < runs; ++run) {
    const PlanResult result = plan(problem, options, random);
    if (result.success) lengths.push_back(result.length);
    iterations.push_back(result.success ? result.iterations : options.max_iterations);
    if (on_run) on_run(run + 1);
  }
  MonteCarloStats stats;
  stats.runs = runs;
  stats.solved = static_cast<int>(lengths.size());
  stats.success_pct = runs > 0 ? 100.0 * stats.solved / runs : 0;
  std::tie(stats.mean_length, stats.std_length) = util::meanAndStd(lengths);
  std::tie(stats.mean_iterations, stats.std_iterations) = util::meanAndStd(iterations);
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return stats;
}

}  // namespace roomba_rrt::planning
