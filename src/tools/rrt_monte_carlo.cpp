// rrt_monte_carlo: the lab's monteCarloRRT from the command line (no ROS master needed).
//
//   rrt_monte_carlo --scenario a|b|c|d|all --runs 200 --seed 42 [--algorithm A]
//                   [--collision points|segments] [--max-iterations N] [--goal-bias P] [--json]
//
// Each scenario is one job: rng(seed) once, then the runs in sequence from that stream, exactly
// as MATLAB's monteCarloRRT does. Jobs (scenarios) run on all cores; a job is never split, so
// the numbers do not depend on the number of threads.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "progress_bar.h"
#include "roomba_rrt/planning/lab/monte_carlo.h"
#include "roomba_rrt/planning/planner.h"
#include "tool_arguments.h"

namespace rp = roomba_rrt::planning;
namespace tools = roomba_rrt::tools;

namespace {

struct Job {
  std::string scenario;
  rp::Problem problem;
  rp::MonteCarloStats stats;
};

void printUsage(std::ostream& out) {
  out << "usage: rrt_monte_carlo --scenario a|b|c|d|all [--runs 200] [--seed 42] [--json]\n"
      << "       rrt_monte_carlo --map FILE --start X,Y --goal X,Y [--runs 200] ...\n"
      << tools::commonFlagsHelp() << "  --runs N                 runs per scenario (default 200)\n"
      << "  --threads N              worker threads (default: all cores)\n"
      << "  --world FILE, --map FILE one query in a world file's room or on a map_server\n"
      << "                           map (the Roomba's radius), from --start X,Y to\n"
      << "                           --goal X,Y, instead of the lab's scenarios\n"
      << "  --json                   print a JSON array instead of a table\n";
}

// A number for JSON: NaN (e.g. std of fewer than two values) becomes null.
std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}

void printJson(const std::vector<Job>& jobs, const rp::PlannerOptions& o, std::uint32_t seed) {
  std::cout << "[\n";
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const rp::MonteCarloStats& s = jobs[i].stats;
    std::cout << "  {\"scenario\": \"" << jobs[i].scenario << "\", \"runs\": " << s.runs
              << ", \"seed\": " << seed << ", \"algorithm\": \"" << rp::toString(o.algorithm)
              << "\", \"collision_check\": \"" << rp::toString(o.collision)
              << "\", \"random_stream\": \"" << rp::toString(o.random_stream)
              << "\", \"success_pct\": " << jsonNumber(s.success_pct)
              << ", \"mean_length\": " << jsonNumber(s.mean_length)
              << ", \"std_length\": " << jsonNumber(s.std_length)
              << ", \"mean_iterations\": " << jsonNumber(s.mean_iterations)
              << ", \"std_iterations\": " << jsonNumber(s.std_iterations)
              << ", \"seconds\": " << jsonNumber(s.seconds) << "}"
              << (i + 1 < jobs.size() ? "," : "") << "\n";
  }
  std::cout << "]\n";
}

void printTable(const std::vector<Job>& jobs, const rp::PlannerOptions& o, int runs,
                std::uint32_t seed) {
  std::printf(
      "RRT Monte Carlo: %d runs per scenario, seed %u (%s stream), algorithm %s, collision %s, "
      "p = %g, step %g, max iterations %d\n",
      runs, seed, rp::toString(o.random_stream).c_str(), rp::toString(o.algorithm).c_str(),
      rp::toString(o.collision).c_str(), o.goal_bias, o.step, o.max_iterations);
  std::printf("%-9s %8s %12s %11s %11s %10s %9s\n", "scenario", "solved %", "mean length",
              "std length", "mean iters", "std iters", "seconds");
  for (const Job& job : jobs) {
    const rp::MonteCarloStats& s = job.stats;
    std::printf("%-9s %8.1f %12.4f %11.4f %11.2f %10.2f %9.3f\n", job.scenario.c_str(),
                s.success_pct, s.mean_length, s.std_length, s.mean_iterations, s.std_iterations,
                s.seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  tools::ToolArguments args;
  int runs = 200;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<Job> jobs;
  try {
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
        printUsage(std::cout);
        return 0;
      }
    }
    args = tools::parseToolArguments(
        argc, argv, {"--runs", "--threads", "--world", "--map", "--start", "--goal"}, {"--json"});
    if (args.tool.count("--runs")) runs = tools::parseIntFlag("--runs", args.tool["--runs"]);
    if (runs < 1) throw std::invalid_argument("--runs: must be >= 1");
    if (args.tool.count("--threads")) {
      threads = std::max(1, tools::parseIntFlag("--threads", args.tool["--threads"]));
    }
    if (args.tool.count("--world") || args.tool.count("--map")) {
      std::string name;
      rp::Problem problem = tools::worldProblem(args, &name);
      jobs.push_back({name, std::move(problem), {}});
    } else {
      const auto scenarios = rp::loadScenarios(args.scenario_file);
      for (const auto& [name, problem] : scenarios) {
        if (args.scenario == "all" || args.scenario == name) jobs.push_back({name, problem, {}});
      }
    }
    if (jobs.empty())
      throw std::invalid_argument("--scenario: unknown scenario '" + args.scenario + "'");
    for (const Job& job : jobs) {
      try {
        rp::validate(job.problem, args.options);
      } catch (const roomba_rrt::util::InvalidInput& invalid) {
        throw invalid.in("scenario " + job.scenario);
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "rrt_monte_carlo: " << e.what() << "\n";
    printUsage(std::cerr);
    return 2;
  }

  const std::uint32_t seed = args.options.seed;
  const int total = runs * static_cast<int>(jobs.size());
  std::atomic<int> done{0};
  std::atomic<std::size_t> next_job{0};
  auto worker = [&] {
    for (std::size_t j; (j = next_job++) < jobs.size();) {
      jobs[j].stats =
          rp::runMonteCarlo(jobs[j].problem, args.options, runs, seed, [&](int) { ++done; });
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::min<int>(threads, jobs.size()); ++t) pool.emplace_back(worker);
  roomba_rrt::tools::ProgressBar progress(total, "runs");
  while (progress.shown() && done < total) {
    progress.update(done);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (std::thread& t : pool) t.join();
  progress.finish(done);

  if (args.tool.count("--json")) {
    printJson(jobs, args.options, seed);
  } else {
    printTable(jobs, args.options, runs, seed);
  }
  return 0;
}
