// planning_bench: how fast is the planner?
//  - BM_SolveScenario: time per query on the lab's scenarios a-d (lab defaults, points mode),
//    seeds continuing one MATLAB stream as rrt_monte_carlo does; counter solved_pct.
//  - BM_IterationOnLargeTree: one RRT iteration (sample, nearest, steer, check, insert) on a
//    tree of 10^6 nodes grown in scenario d's world, with the grid index vs brute force.
//  - BM_GrowTree: a whole exploration run of N iterations from the start (index only).
// Run: scripts/bench, or devel/lib/roomba_rrt/planning_bench after a Release build.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>

#include "roomba_rrt/planning/planner.h"
#include "roomba_rrt/planning/planners/rrt.h"

namespace rp = roomba_rrt::planning;

namespace {

const std::map<std::string, rp::Problem>& scenarios() {
  static const auto s = rp::loadScenarios(ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml");
  return s;
}

void BM_SolveScenario(benchmark::State& state, const std::string& name, rp::NearestSearch nn) {
  const rp::Problem& problem = scenarios().at(name);
  rp::PlannerOptions options;
  options.nearest = nn;
  rp::MatlabRandom stream(42);
  int64_t solved = 0, runs = 0;
  for (auto _ : state) {
    const rp::PlanResult r = rp::plan(problem, options, stream);
    benchmark::DoNotOptimize(r.length);
    solved += r.success;
    ++runs;
  }
  state.counters["solved_pct"] = 100.0 * solved / runs;
}

// A tree of `nodes` nodes in scenario d's world. With goal_tolerance 0 the planner never stops:
// the tree passes the gaps and fills the whole free space (duplicates of the goal are not added).
const rp::Tree& largeTree(int nodes) {
  static std::map<int, rp::Tree> cache;
  auto found = cache.find(nodes);
  if (found != cache.end()) return found->second;
  rp::PlannerOptions options;
  options.goal_tolerance = 0;
  options.max_iterations = nodes + nodes / 2;  // enough: few iterations are blocked
  rp::Tree tree;
  rp::plan(
      scenarios().at("d"), options,
      [&](const rp::Tree& t, int) {
        if (tree.size() == 0 && t.size() >= nodes) tree = t;  // copy once, at `nodes`
      },
      100);
  tree.nodes.resize(nodes);
  tree.parent.resize(nodes);
  return cache.emplace(nodes, std::move(tree)).first->second;
}

void BM_IterationOnLargeTree(benchmark::State& state, rp::NearestSearch nn) {
  const int nodes = static_cast<int>(state.range(0));
  const rp::Problem& problem = scenarios().at("d");
  rp::PlannerOptions options;  // lab defaults: p = 0.1, step 0.2
  rp::Tree tree = largeTree(nodes);
  tree.reserve(nodes + nodes / 10 + 1);  // no reallocation inside the measurement
  const auto nearest = rp::makeNearestNeighbors(nn);
  nearest->clear(problem.bounds, tree.nodes);
  for (int i = 0; i < tree.size(); ++i) nearest->add(tree.nodes[i], i);
  const rp::CollisionChecker checker(problem.obstacles, options.collision);
  const rp::FreeSpaceSampler sampler(problem.bounds, checker, options.max_rejection_tries);
  rp::PlanRandom random(7, rp::RandomStream::kMatlab);
  const rp::PlannerParts parts{random, sampler, *nearest, checker};
  for (auto _ : state) {
    const auto q_rand = rp::sampleTarget(problem, options, parts);
    benchmark::DoNotOptimize(rp::extendTree(tree, *nearest, checker, *q_rand, options.step));
  }
  state.counters["iterations_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The nearest-neighbour query alone (free-space points, as RRT samples), on the same trees.
void BM_NearestOnLargeTree(benchmark::State& state, rp::NearestSearch nn) {
  const int nodes = static_cast<int>(state.range(0));
  const rp::Problem& problem = scenarios().at("d");
  const rp::Tree& tree = largeTree(nodes);
  const auto nearest = rp::makeNearestNeighbors(nn);
  nearest->clear(problem.bounds, tree.nodes);
  for (int i = 0; i < tree.size(); ++i) nearest->add(tree.nodes[i], i);
  const rp::CollisionChecker checker(problem.obstacles, rp::CollisionCheck::kPoints);
  const rp::FreeSpaceSampler sampler(problem.bounds, checker, 1000);
  rp::MatlabRandom random(9);
  std::vector<rp::Point2> queries(1 << 16);
  for (rp::Point2& q : queries) q = *sampler.sample(random);  // free space, as RRT samples
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(nearest->nearest(queries[i++ & (queries.size() - 1)]));
  }
}

void BM_GrowTree(benchmark::State& state) {
  rp::PlannerOptions options;
  options.goal_tolerance = 0;
  options.max_iterations = static_cast<int>(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(rp::plan(scenarios().at("d"), options).tree.size());
  }
  state.counters["iterations_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * state.range(0)), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(BM_SolveScenario, a, "a", rp::NearestSearch::kIndex)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SolveScenario, b, "b", rp::NearestSearch::kIndex)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SolveScenario, c, "c", rp::NearestSearch::kIndex)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SolveScenario, d, "d", rp::NearestSearch::kIndex)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SolveScenario, a_brute_force, "a", rp::NearestSearch::kBruteForce)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SolveScenario, d_brute_force, "d", rp::NearestSearch::kBruteForce)
    ->Unit(benchmark::kMicrosecond);
// Each measurement adds at most 10 % to the tree (10^4 iterations on the smallest), so its size
// stays about what the name says.
const int kLargeTreeBenchmarks = [] {
  for (int nodes : {10'000, 100'000, 1'000'000}) {
    const std::string size = "/" + std::to_string(nodes);
    benchmark::RegisterBenchmark(("BM_IterationOnLargeTree/index" + size).c_str(),
                                 BM_IterationOnLargeTree, rp::NearestSearch::kIndex)
        ->Arg(nodes)
        ->Iterations(std::max(nodes / 10, 10'000))  // fewer would mostly time the warm-up
        ->Repetitions(5)                            // short runs: report the median of five
        ->ReportAggregatesOnly(true)
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("BM_IterationOnLargeTree/brute_force" + size).c_str(),
                                 BM_IterationOnLargeTree, rp::NearestSearch::kBruteForce)
        ->Arg(nodes)
        ->Iterations(std::min(nodes / 10, 300))
        ->Unit(benchmark::kMicrosecond);
  }
  return 0;
}();
BENCHMARK_CAPTURE(BM_NearestOnLargeTree, index, rp::NearestSearch::kIndex)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kNanosecond);
BENCHMARK(BM_GrowTree)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->Iterations(3);

BENCHMARK_MAIN();
