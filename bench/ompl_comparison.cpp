// The lab's RRT (rrt_planning) against OMPL 1.5's stock geometric::RRT, on the same problems with
// the same parameters and the same collision semantics, timed in the same process (CPU time of
// the solving thread less the clock reading's own cost, median over many solves after a warm-up).
//
//   ompl_comparison                      scenarios a-d x {points, segments} and the growth rows,
//                                        as a Markdown table
//   ompl_comparison --json               the same figures as JSON (read by scripts/bench)
//   ompl_comparison --runs 500 --warmup 20 --growth 10000,100000,1000000 --growth-reps 3
//   ompl_comparison --world config/roomba_world_furnished.yaml --room-runs 5
//                                        the furnished-room rows' world and solves per pair
//   ompl_comparison --plan-once ours|ompl --iterations 1000000
//                                        one growth plan, nothing else (for peak-RSS figures)
//
// Both sides get: step (OMPL's range) 0.2, goal bias 0.1, goal tolerance 1e-3 (OMPL's GoalState
// threshold), at most N iterations (OMPL's IterationTerminationCondition), the box bounds, and
// the planning library's own CollisionChecker as the motion test (OMPL: a MotionValidator):
//   points    a motion is valid when its end state is free (the lab's "for simplicity" check);
//   segments  a motion is valid when the segment misses every circle (exact segment-circle test).
// Growth rows: scenario d's world with a goal that is never accepted (the library's
// goal_tolerance 0; for OMPL a GoalState whose isSatisfied() is always false), so both planners
// run exactly N iterations while the goal bias still pulls one sample in ten towards (9, 1).
// One difference remains by design and is reported next to the table: OMPL samples the whole box
// and discards steps that end in an obstacle, while the lab rejection-samples the free space.
// This changes the success rates (mostly on scenario d), not the work done per iteration.
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "arguments.h"
#include "ompl_lab.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace {

using namespace roomba_rrt::bench;  // NOLINT: the measurement shared with map_comparison

struct ScenarioRow {
  std::string scenario, mode;
  Summary ours, ompl;
};

struct GrowthRow {
  unsigned iterations = 0;
  double ours_ns_per_iteration = 0, ompl_ns_per_iteration = 0;
};

/// The growth rows' options: the lab's, with a goal that is never reached (goal_tolerance 0),
/// so both planners run exactly the requested number of iterations in scenario d's world.
rp::PlannerOptions unreachableGoal() {
  rp::PlannerOptions options;
  options.goal_tolerance = 0;
  return options;
}

struct Config {
  int runs = 500;
  int warmup = 20;
  std::vector<unsigned> growth = {10000, 100000, 1000000};
  int growth_reps = 3;
  bool json = false;
  std::string plan_once;  // "ours" or "ompl"
  unsigned iterations = 1000000;
  std::string scenarios_file = ROOMBA_RRT_CONFIG_DIR "/rrt_scenarios.yaml";
  std::string world_file = ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml";
  int room_runs = 5;            // solves per start/goal pair and side in the room rows
  int room_iterations = 20000;  // the room's RRT and RRT-Connect: max_iterations of both sides
  bool room_only = false;       // only the room rows (--room-only)
};

const char* modeName(rp::CollisionCheck c) {
  return c == rp::CollisionCheck::kPoints ? "points" : "segments";
}

std::vector<ScenarioRow> runScenarios(const std::map<std::string, rp::Problem>& scenarios,
                                      const Config& cfg) {
  std::vector<ScenarioRow> rows;
  for (const char* name : {"a", "b", "c", "d"}) {
    const rp::Problem& problem = scenarios.at(name);
    for (rp::CollisionCheck mode : {rp::CollisionCheck::kPoints, rp::CollisionCheck::kSegments}) {
      rp::PlannerOptions options;  // the lab's defaults: step 0.2, bias 0.1, eps 1e-3, 1000 it.
      options.collision = mode;
      const unsigned iterations = static_cast<unsigned>(options.max_iterations);
      ScenarioRow row{name, modeName(mode), {}, {}};
      OmplLabRrt ompl(problem, options);
      row.ompl = measure(cfg.warmup, cfg.runs, [&](int) { return ompl.solve(iterations); });
      row.ours = measure(cfg.warmup, cfg.runs, [&](int i) {
        return solveOurs(problem, options, iterations, 42u + static_cast<std::uint32_t>(i));
      });
      rows.push_back(row);
      std::cerr << "scenario " << name << " " << modeName(mode) << ": ours "
                << row.ours.median_seconds * 1e6 << " us, OMPL " << row.ompl.median_seconds * 1e6
                << " us\n";
    }
  }
  return rows;
}

std::vector<GrowthRow> runGrowth(const rp::Problem& world, const Config& cfg) {
  std::vector<GrowthRow> rows;
  const rp::PlannerOptions options = unreachableGoal();  // points mode, as the lab
  for (unsigned n : cfg.growth) {
    OmplLabRrt ompl(world, options);
    GrowthRow row;
    row.iterations = n;
    const int warmup = n <= 100000 ? 1 : 0;
    row.ompl_ns_per_iteration =
        measure(warmup, cfg.growth_reps, [&](int) { return ompl.solve(n); }).median_seconds * 1e9 /
        n;
    row.ours_ns_per_iteration =
        measure(warmup, cfg.growth_reps,
                [&](int i) { return solveOurs(world, options, n, 42u + i); })
            .median_seconds *
        1e9 / n;
    rows.push_back(row);
    std::cerr << "growth " << n << ": ours " << row.ours_ns_per_iteration << " ns/it, OMPL "
              << row.ompl_ns_per_iteration << " ns/it\n";
  }
  return rows;
}

// ---------------------------------------------------------------------------------------------
// The furnished room (issue 9): the simulator's world for a robot of radius 0.17 (the world's),
// collision_check segments, 20 fixed start/goal pairs. Both sides plan in the same grown world
// with the same checker (OmplLab above).

constexpr int kRoomPairs = 20;

bool plannable(const rp::Problem& problem) {
  try {
    rp::validate(problem, {});
    return true;
  } catch (const roomba_rrt::util::InvalidInput&) {
    return false;
  }
}

/// 20 start/goal pairs drawn once from MATLAB's stream seeded 2024 in the shrunk bounds, each
/// valid for the robot (not in grown furniture) and at least 3 m apart.
std::vector<rp::Problem> roomQueries(const rp::Problem& room) {
  rp::MatlabRandom random(2024);
  const rp::Bounds b = rp::shrink(room.bounds, rp::robotMargin(room));
  std::vector<rp::Problem> out;
  while (out.size() < kRoomPairs) {
    rp::Problem p = room;
    p.start = {random.uniform(b.x_min, b.x_max), random.uniform(b.y_min, b.y_max)};
    p.goal = {random.uniform(b.x_min, b.x_max), random.uniform(b.y_min, b.y_max)};
    if (rp::distance(p.start, p.goal) >= 3 && plannable(p)) out.push_back(p);
  }
  return out;
}

struct RoomRow {
  std::string name;     // rrt, rrt_connect, rrt_star_10ms, rrt_star_100ms
  double budget_s = 0;  // RRT* rows: the CPU-time budget of each solve
  Summary ours, ompl;
  /// RRT, RRT-Connect: OMPL as a user sets it up, the exact point check every kUserCheckStep.
  std::optional<Summary> ompl_user;
};

/// The user's OMPL in the room: DiscreteMotionValidator every centimetre (the room has no cells;
/// a user who wants no corner cut picks a step well below the furniture's legs and margins).
constexpr double kUserCheckStep = 0.01;  // m

/// The lab's options for the room: segments, step 0.2, bias 0.1, eps 1e-3, and `iterations`
/// (the same limit for OMPL; enough that every pair is solved); ours draws from the fast stream,
/// as scenario `room` does.
rp::PlannerOptions roomOptions(rp::Algorithm algorithm, int iterations = 20000) {
  rp::PlannerOptions options;
  options.algorithm = algorithm;
  options.collision = rp::CollisionCheck::kSegments;
  options.max_iterations = iterations;
  options.random_stream = rp::RandomStream::kFast;  // as the service plans in the room
  return options;
}

/// Solve time of RRT (or RRT-Connect) against OMPL's, run `solve_i` for pair i % 20.
template <typename OmplPlanner>
RoomRow roomTimeRow(const std::string& name, const std::vector<rp::Problem>& queries,
                    rp::Algorithm algorithm, const Config& cfg) {
  const rp::PlannerOptions options = roomOptions(algorithm, cfg.room_iterations);
  std::vector<std::unique_ptr<OmplLab<OmplPlanner>>> ompl, ompl_user;
  for (const rp::Problem& q : queries) {
    ompl.push_back(std::make_unique<OmplLab<OmplPlanner>>(q, options));
    ompl_user.push_back(
        std::make_unique<OmplLab<OmplPlanner>>(q, options, MotionCheck{kUserCheckStep}));
  }
  const int runs = kRoomPairs * cfg.room_runs;
  RoomRow row{name, 0, {}, {}, {}};
  const auto iterations = static_cast<unsigned>(options.max_iterations);
  row.ompl =
      measure(kRoomPairs, runs, [&](int i) { return ompl[i % kRoomPairs]->solve(iterations); });
  row.ompl_user = measure(kRoomPairs, runs,
                          [&](int i) { return ompl_user[i % kRoomPairs]->solve(iterations); });
  row.ours = measure(kRoomPairs, runs, [&](int i) {
    return solveOurs(queries[i % kRoomPairs], options, iterations,
                     42u + static_cast<std::uint32_t>(i));
  });
  return row;
}

/// RRT*'s mean path length after the same CPU-time budget as OMPL's RRTstar.
RoomRow roomStarRow(const std::vector<rp::Problem>& queries, double budget, const Config& cfg) {
  const rp::PlannerOptions options = roomOptions(rp::Algorithm::kRrtStar);
  std::vector<std::unique_ptr<OmplLab<og::RRTstar>>> ompl;
  std::vector<unsigned> iterations;
  for (const rp::Problem& q : queries) {
    ompl.push_back(std::make_unique<OmplLab<og::RRTstar>>(q, options));
    iterations.push_back(iterationsWithin(q, options, budget));
  }
  const int runs = kRoomPairs * cfg.room_runs;
  RoomRow row{"rrt_star_" + std::to_string(static_cast<int>(budget * 1000 + 0.5)) + "ms",
              budget,
              {},
              {},
              std::nullopt};
  row.ompl = measure(0, runs, [&](int i) { return ompl[i % kRoomPairs]->solveFor(budget); });
  row.ours = measure(0, runs, [&](int i) {
    const int pair = i % kRoomPairs;
    return solveOurs(queries[pair], options, iterations[pair], 42u + static_cast<std::uint32_t>(i));
  });
  return row;
}

std::vector<RoomRow> runRoom(const Config& cfg) {
  const rp::Problem room = roomba_rrt::world_planning::loadRoom(cfg.world_file);
  const std::vector<rp::Problem> queries = roomQueries(room);
  std::vector<RoomRow> rows;
  rows.push_back(roomTimeRow<og::RRT>("rrt", queries, rp::Algorithm::kRrt, cfg));
  rows.push_back(
      roomTimeRow<og::RRTConnect>("rrt_connect", queries, rp::Algorithm::kRrtConnect, cfg));
  for (double budget : {0.01, 0.1}) rows.push_back(roomStarRow(queries, budget, cfg));
  for (const RoomRow& r : rows) {
    std::cerr << "room " << r.name << ": ours " << r.ours.median_seconds * 1e6 << " us, L "
              << r.ours.mean_length << ", " << r.ours.solved_percent << " %; OMPL "
              << r.ompl.median_seconds * 1e6 << " us, L " << r.ompl.mean_length << ", "
              << r.ompl.solved_percent << " %";
    if (r.ompl_user) {
      std::cerr << "; OMPL with a user's checker " << r.ompl_user->median_seconds * 1e6 << " us";
    }
    std::cerr << "\n";
  }
  return rows;
}

// ---------------------------------------------------------------------------------------------
// Output.

void printJson(const std::vector<ScenarioRow>& scenarios, const std::vector<GrowthRow>& growth,
               const std::vector<RoomRow>& room, const Config& cfg) {
  auto side = [](const Summary& s) {
    return "{\"solved_percent\": " + num(s.solved_percent, 2) +
           ", \"mean_length\": " + num(s.mean_length, 4) +
           ", \"median_us\": " + num(s.median_seconds * 1e6, 2) + "}";
  };
  std::cout << "{\n  \"runs\": " << cfg.runs << ", \"warmup\": " << cfg.warmup
            << ", \"ompl_version\": \"" << kOmplVersion << "\",\n  \"scenarios\": [\n";
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const ScenarioRow& r = scenarios[i];
    std::cout << "    {\"scenario\": \"" << r.scenario << "\", \"mode\": \"" << r.mode
              << "\", \"ours\": " << side(r.ours) << ", \"ompl\": " << side(r.ompl) << "}"
              << (i + 1 < scenarios.size() ? "," : "") << "\n";
  }
  std::cout << "  ],\n  \"growth\": [\n";
  for (std::size_t i = 0; i < growth.size(); ++i) {
    const GrowthRow& g = growth[i];
    std::cout << "    {\"iterations\": " << g.iterations
              << ", \"ours_ns_per_iteration\": " << num(g.ours_ns_per_iteration, 1)
              << ", \"ompl_ns_per_iteration\": " << num(g.ompl_ns_per_iteration, 1) << "}"
              << (i + 1 < growth.size() ? "," : "") << "\n";
  }
  std::cout << "  ],\n  \"room_runs\": " << kRoomPairs * cfg.room_runs << ",\n  \"room\": [\n";
  for (std::size_t i = 0; i < room.size(); ++i) {
    const RoomRow& r = room[i];
    std::cout << "    {\"row\": \"" << r.name << "\", \"budget_ms\": " << num(r.budget_s * 1e3, 1)
              << ", \"ours\": " << side(r.ours) << ", \"ompl\": " << side(r.ompl)
              << (r.ompl_user ? ", \"ompl_user\": " + side(*r.ompl_user) : std::string()) << "}"
              << (i + 1 < room.size() ? "," : "") << "\n";
  }
  std::cout << "  ]\n}\n";
}

void printMarkdown(const std::vector<ScenarioRow>& scenarios, const std::vector<GrowthRow>& growth,
                   const std::vector<RoomRow>& room, const Config& cfg) {
  std::cout << "RRT vs OMPL " << kOmplVersion << " geometric::RRT (" << cfg.runs
            << " runs per row after " << cfg.warmup
            << " warm-up runs; median CPU time per solve)\n\n"
            << "| scenario | mode | solved % ours | solved % OMPL | mean length ours | "
               "mean length OMPL | µs ours | µs OMPL | ours/OMPL |\n"
            << "|---|---|---|---|---|---|---|---|---|\n";
  for (const ScenarioRow& r : scenarios) {
    std::cout << "| " << r.scenario << " | " << r.mode << " | " << num(r.ours.solved_percent, 1)
              << " | " << num(r.ompl.solved_percent, 1) << " | " << num(r.ours.mean_length, 2)
              << " | " << num(r.ompl.mean_length, 2) << " | " << num(r.ours.median_seconds * 1e6, 1)
              << " | " << num(r.ompl.median_seconds * 1e6, 1) << " | "
              << num(r.ours.median_seconds / r.ompl.median_seconds, 3) << " |\n";
  }
  std::cout << "\nGrowth (scenario d's world, goal never reached, points mode; median of "
            << cfg.growth_reps << ")\n\n"
            << "| iterations | ns/iteration ours | ns/iteration OMPL | ours/OMPL |\n"
            << "|---|---|---|---|\n";
  for (const GrowthRow& g : growth) {
    std::cout << "| " << g.iterations << " | " << num(g.ours_ns_per_iteration, 1) << " | "
              << num(g.ompl_ns_per_iteration, 1) << " | "
              << num(g.ours_ns_per_iteration / g.ompl_ns_per_iteration, 3) << " |\n";
  }
  std::cout << "\nOMPL samples the whole box and discards steps that end in an obstacle; the lab "
               "rejection-samples the free space, so success rates differ (mostly on d).\n";
  std::cout << "\nFurnished room, robot radius 0.17, segments, " << kRoomPairs
            << " start/goal pairs x " << cfg.room_runs
            << " (RRT, RRT-Connect: median CPU time per solve; RRT*: mean length after the same "
               "CPU-time budget)\n\n"
            << "| row | solved % ours | solved % OMPL | mean length ours | mean length OMPL | "
               "µs ours | µs OMPL | ours/OMPL time | ours/OMPL length |\n"
            << "|---|---|---|---|---|---|---|---|---|\n";
  for (const RoomRow& r : room) {
    std::cout << "| " << r.name << " | " << num(r.ours.solved_percent, 1) << " | "
              << num(r.ompl.solved_percent, 1) << " | " << num(r.ours.mean_length, 3) << " | "
              << num(r.ompl.mean_length, 3) << " | " << num(r.ours.median_seconds * 1e6, 1) << " | "
              << num(r.ompl.median_seconds * 1e6, 1) << " | "
              << num(r.ours.median_seconds / r.ompl.median_seconds, 3) << " | "
              << num(r.ours.mean_length / r.ompl.mean_length, 3) << " |\n";
  }
}

// ---------------------------------------------------------------------------------------------
// Command line.

const char* const kUsage =
    "usage: ompl_comparison [--json] [--runs N] [--warmup N] [--growth N,N,...]"
    " [--growth-reps N] [--scenarios FILE]\n"
    "                       [--world FILE] [--room-runs N] [--room-iterations N]"
    " [--room-only]\n"
    "       ompl_comparison --plan-once ours|ompl [--iterations N]\n";

Config parseArgs(int argc, char** argv) {
  Config cfg;
  roomba_rrt::bench::Arguments args(argc, argv, "ompl_comparison", kUsage);
  while (args.next()) {
    if (args.is("--json")) {
      cfg.json = true;
    } else if (args.is("--runs")) {
      cfg.runs = args.count(1);
    } else if (args.is("--warmup")) {
      cfg.warmup = args.count();
    } else if (args.is("--growth-reps")) {
      cfg.growth_reps = args.count(1);
    } else if (args.is("--growth")) {
      cfg.growth.clear();
      std::stringstream list(args.value());
      for (std::string item; std::getline(list, item, ',');) {
        if (!item.empty()) cfg.growth.push_back(static_cast<unsigned>(args.countOf(item)));
      }
    } else if (args.is("--plan-once")) {
      cfg.plan_once = args.value();
      if (cfg.plan_once != "ours" && cfg.plan_once != "ompl")
        args.fail("--plan-once: ours or ompl");
    } else if (args.is("--iterations")) {
      cfg.iterations = static_cast<unsigned>(args.count());
    } else if (args.is("--scenarios")) {
      cfg.scenarios_file = args.value();
    } else if (args.is("--world")) {
      cfg.world_file = args.value();
    } else if (args.is("--room-only")) {
      cfg.room_only = true;
    } else if (args.is("--room-iterations")) {
      cfg.room_iterations = args.count();
    } else if (args.is("--room-runs")) {
      cfg.room_runs = args.count(1);
    } else {
      args.unknown();
    }
  }
  return cfg;
}

/// One plan, nothing else, then its CPU time and the process's peak RSS (MB) as JSON.
int planOnce(const rp::Problem& world, const Config& cfg) {
  const rp::PlannerOptions options = unreachableGoal();
  Solve s;
  if (cfg.plan_once == "ompl") {
    OmplLabRrt ompl(world, options);
    s = ompl.solve(cfg.iterations);
  } else {
    s = solveOurs(world, options, cfg.iterations, 42u);
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::cout << "{\"planner\": \"" << cfg.plan_once << "\", \"iterations\": " << cfg.iterations
            << ", \"seconds\": " << num(s.seconds, 3)
            << ", \"solved\": " << (s.solved ? "true" : "false")
            << ", \"peak_rss_mb\": " << num(usage.ru_maxrss / 1024.0, 1) << "}\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Config cfg = parseArgs(argc, argv);
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(42);  // before any planner exists: OMPL seeds every RNG from this one
  g_clock_overhead = clockOverhead();

  std::map<std::string, rp::Problem> scenarios;
  try {
    scenarios = rp::loadScenarios(cfg.scenarios_file);
    for (const char* name : {"a", "b", "c", "d"}) {
      if (scenarios.count(name) == 0) throw std::runtime_error(std::string("no scenario ") + name);
    }
  } catch (const std::exception& e) {
    std::cerr << "ompl_comparison: cannot load scenarios from " << cfg.scenarios_file << ": "
              << e.what() << "\n";
    return 1;
  }
  const rp::Problem& growth_world = scenarios.at("d");
  if (!cfg.plan_once.empty()) return planOnce(growth_world, cfg);

  const std::vector<ScenarioRow> rows =
      cfg.room_only ? std::vector<ScenarioRow>{} : runScenarios(scenarios, cfg);
  const std::vector<GrowthRow> growth =
      cfg.room_only ? std::vector<GrowthRow>{} : runGrowth(growth_world, cfg);
  std::vector<RoomRow> room;
  try {
    room = runRoom(cfg);
  } catch (const std::exception& e) {
    std::cerr << "ompl_comparison: " << cfg.world_file << ": " << e.what() << "\n";
    return 1;
  }
  if (cfg.json) {
    printJson(rows, growth, room, cfg);
  } else {
    printMarkdown(rows, growth, room, cfg);
  }
  return 0;
}
