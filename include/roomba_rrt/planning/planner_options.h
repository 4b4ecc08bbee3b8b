// How to plan: the lab's parameters (step, goal bias, iterations, tolerance) and the choices
// that go beyond the lab (algorithm, collision mode, nearest-neighbour structure, smoothing).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace roomba_rrt::planning {

enum class Algorithm {
  kRrt,         ///< "rrt": the lab's RRT (default).
  kRrtConnect,  ///< "rrt_connect": two trees (start and goal) that grow towards each other.
  kRrtStar,     ///< "rrt_star": RRT with best-parent choice and rewiring; uses all iterations.
  /// "region_astar": on a map only, A* over its regions then string pulling
  /// (planners/region_astar.h); deterministic, no tree; step, goal_bias, max_iterations, seed,
  /// collision and smooth do not apply (every edge is swept exactly).
  kRegionAStar,
};

enum class CollisionCheck {
  kPoints,    ///< "points": only each new node is checked (the lab, "for simplicity").
  kSegments,  ///< "segments": each new edge is checked exactly against every circle.
};

enum class NearestSearch {
  kIndex,       ///< "index": the uniform bucket grid (GridNearestNeighbors), the default.
  kBruteForce,  ///< "brute_force": the lab's linear scan, kept as the reference.
};

enum class RandomStream {
  kMatlab,  ///< "matlab": MATLAB's rng(seed) stream (MT19937), the lab's answers bit for bit.
  kFast,    ///< "fast": xoshiro256+ (FastRandom), seeded in nanoseconds; not MATLAB's numbers.
};

/// The largest `max_iterations` the library accepts by default (a 10^6-iteration plan peaks at
/// 41 MB resident, tree and index included). Callers may pass their own cap to validate().
inline constexpr int kDefaultMaxIterationsCap = 5'000'000;

struct PlannerOptions {
  double step = 0.2;             ///< Delta, the longest extension (m).
  double goal_bias = 0.1;        ///< p: a draw r < p makes the goal the random point.
  int max_iterations = 1000;     ///< iterations before giving up.
  double goal_tolerance = 1e-3;  ///< epsilon: stop when a new node is closer than this to the goal.
                                 ///< 0 never stops early (pure exploration, for benchmarks).
  Algorithm algorithm = Algorithm::kRrt;
  CollisionCheck collision = CollisionCheck::kPoints;
  NearestSearch nearest = NearestSearch::kIndex;
  bool smooth = false;      ///< shortcut-smooth the path found (deterministic, seeded).
  std::uint32_t seed = 42;  ///< MATLAB rng(seed); 0 behaves as MATLAB's rng(0) (MT seed 5489).
  /// The stream `seed` seeds (plan_random.h). The lab's by default; the service and the tools
  /// choose kFast for rooms and maps, which MATLAB's lab never had (doc/planning.md).
  RandomStream random_stream = RandomStream::kMatlab;
  int max_rejection_tries = 100000;  ///< draws of one free point before the space counts as full.
  int smoothing_tries = 200;         ///< random shortcut attempts when `smooth` is set.
  double max_planning_time = 0;      ///< wall-clock budget (s); 0 = none. See StopCondition.
};

std::optional<Algorithm> parseAlgorithm(const std::string& name);
std::optional<CollisionCheck> parseCollisionCheck(const std::string& name);
std::optional<NearestSearch> parseNearestSearch(const std::string& name);
std::optional<RandomStream> parseRandomStream(const std::string& name);
std::string toString(Algorithm algorithm);
std::string toString(CollisionCheck collision);
std::string toString(NearestSearch nearest);
std::string toString(RandomStream stream);

}  // namespace roomba_rrt::planning
