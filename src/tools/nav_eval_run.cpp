#include "nav_eval_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <queue>
#include <random>

#include "roomba_rrt/exploration/navigate_unknown.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world_planning/room_problem.h"

namespace roomba_rrt::tools {
namespace {

using planning::Point2;

/// Whether the disc of radius `margin` around p is inside the room (the map's extent) and clear
/// of the furniture and the map's blocked cells.
bool discFree(const world::World& w, const Point2& p, double margin) {
  if (p.x < w.room.origin.x + margin || p.x > w.room.origin.x + w.room.width - margin ||
      p.y < w.room.origin.y + margin || p.y > w.room.origin.y + w.room.height - margin) {
    return false;
  }
  for (const geometry::Circle& c : w.room.circles) {
    if (geometry::distance(p, c.center) < c.radius + margin) return false;
  }
  for (const geometry::Rectangle& r : w.room.rectangles) {
    if (geometry::distance(r, p) < margin) return false;
  }
  return !w.room.map || !geometry::blockedWithin(*w.room.map, p, margin);
}

/// Whether the disc swept along a-b stays free (the room is convex: the end points decide it).
bool sweepFree(const world::World& w, const Point2& a, const Point2& b, double margin) {
  if (!discFree(w, a, margin) || !discFree(w, b, margin)) return false;
  const geometry::Segment sweep{a, b};
  for (const geometry::Circle& c : w.room.circles) {
    if (geometry::distance(c.center, geometry::closestPoint(sweep, c.center)) < c.radius + margin) {
      return false;
    }
  }
  for (const geometry::Rectangle& r : w.room.rectangles) {
    if (geometry::distance(r, sweep) < margin) return false;
  }
  return !w.room.map || !geometry::segmentMeetsBlocked(*w.room.map, sweep, margin);
}

/// Records every finished plan's time.
class TimedPlanner final : public navigation::PathPlanner {
 public:
  TimedPlanner(std::unique_ptr<navigation::PathPlanner> inner, std::vector<double>& times)
      : inner_(std::move(inner)), times_(times) {}
  void request(const Point2& start, const Point2& goal) override { inner_->request(start, goal); }
  bool poll(navigation::PlanReply& reply) override {
    if (!inner_->poll(reply)) return false;
    times_.push_back(reply.planning_ms);
    return true;
  }
  void cancel() override { inner_->cancel(); }

 private:
  std::unique_ptr<navigation::PathPlanner> inner_;
  std::vector<double>& times_;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace

double shortestDiscPathLength(const world::World& world, const robot::Pose2D& start,
                              const robot::Pose2D& goal, double cell) {
  const double inf = std::numeric_limits<double>::infinity();
  const double r = world.robot().radius;
  const Point2 s{start.x, start.y}, g{goal.x, goal.y};
  if (!discFree(world, s, r - 1e-9) || !discFree(world, g, r - 1e-9)) return inf;
  if (sweepFree(world, s, g, r)) return std::hypot(g.x - s.x, g.y - s.y);
  const int nx = static_cast<int>(std::ceil(world.room.width / cell));
  const int ny = static_cast<int>(std::ceil(world.room.height / cell));
  const Point2 o = world.room.origin;
  const auto centre = [&](int i, int j) {
    return Point2{o.x + (i + 0.5) * cell, o.y + (j + 0.5) * cell};
  };
  std::vector<char> free(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) free[j * nx + i] = discFree(world, centre(i, j), r);
  }
  // The free cells nearest to start and goal that the disc reaches in a straight line.
  const auto anchor = [&](const Point2& p) {
    int best = -1;
    double best_d = inf;
    const int ci = static_cast<int>((p.x - o.x) / cell), cj = static_cast<int>((p.y - o.y) / cell);
    for (int j = std::max(0, cj - 3); j <= std::min(ny - 1, cj + 3); ++j) {
      for (int i = std::max(0, ci - 3); i <= std::min(nx - 1, ci + 3); ++i) {
        const double d = std::hypot(centre(i, j).x - p.x, centre(i, j).y - p.y);
        if (free[j * nx + i] && d < best_d && sweepFree(world, p, centre(i, j), r - 1e-9)) {
          best = j * nx + i;
          best_d = d;
        }
      }
    }
    return best;
  };
  const int from = anchor(s), to = anchor(g);
  if (from < 0 || to < 0) return inf;
  static const int kMoves[16][2] = {{1, 0},  {-1, 0},  {0, 1},   {0, -1}, {1, 1},  {1, -1},
                                    {-1, 1}, {-1, -1}, {1, 2},   {2, 1},  {-1, 2}, {-2, 1},
                                    {1, -2}, {2, -1},  {-1, -2}, {-2, -1}};
  std::vector<double> dist(free.size(), inf);
  std::vector<int> parent(free.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[from] = 0;
  open.push({0, from});
  while (!open.empty()) {
    const auto [d, c] = open.top();
    open.pop();
    if (d > dist[c]) continue;
    if (c == to) break;
    const int ci = c % nx, cj = c / nx;
    for (const auto& m : kMoves) {
      const int i = ci + m[0], j = cj + m[1];
      if (i < 0 || j < 0 || i >= nx || j >= ny || !free[j * nx + i]) continue;
      // Knight moves pass between two cells: both must be free.
      if (std::abs(m[0]) + std::abs(m[1]) == 3) {
        const int sx = m[0] > 0 ? 1 : -1, sy = m[1] > 0 ? 1 : -1;
        const bool wide = std::abs(m[0]) == 2;
        const int ai = wide ? ci + sx : ci, aj = wide ? cj : cj + sy;
        if (!free[aj * nx + ai] || !free[(cj + sy) * nx + ci + sx]) continue;
      }
      const double nd = d + cell * std::hypot(m[0], m[1]);
      const int n = j * nx + i;
      if (nd < dist[n]) {
        dist[n] = nd;
        parent[n] = c;
        open.push({nd, n});
      }
    }
  }
  if (dist[to] == inf) return inf;
  std::vector<Point2> path{g};
  for (int c = to; c >= 0; c = parent[c]) path.push_back(centre(c % nx, c / nx));
  path.push_back(s);
  std::reverse(path.begin(), path.end());
  // Pull taut: from each kept point, jump to the farthest point visible to the disc.
  double length = 0;
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = path.size() - 1;
    while (j > i + 1 && !sweepFree(world, path[i], path[j], r)) --j;
    length += std::hypot(path[j].x - path[i].x, path[j].y - path[i].y);
    i = j;
  }
  return length;
}

namespace {

/// Drives the simulator's robot towards `run.goal` with `command(bumper, pose)` until `nav`'s goal
/// is no longer active or `timeout_s` robot seconds pass: what a user notices goes into `run`
/// (bumps, time, length driven, a pose every 6th tick, and "timeout" or nav's message when it
/// was not reached).
template <class Nav, class Command>
void driveGoal(sim::Simulator& simulator, const Nav& nav, double timeout_s, GoalRun& run,
               Command command) {
  const double step = simulator.world().step;
  const long max_ticks = std::lround(timeout_s / step);
  long tick = 0;
  for (; tick < max_ticks && nav.outcome() == navigation::GoalOutcome::kActive; ++tick) {
    const robot::BumperState bumper = simulator.senseContact();
    run.bumps += bumper.pressed ? 1 : 0;
    const robot::Pose2D before = simulator.pose();
    simulator.move(command(bumper, before));
    run.driven_m += std::hypot(simulator.pose().x - before.x, simulator.pose().y - before.y);
    if (tick % 6 == 0) run.trace.push_back(simulator.pose());
  }
  run.time_s = static_cast<double>(tick) * step;
  run.reached = nav.outcome() == navigation::GoalOutcome::kSucceeded;
  if (nav.outcome() == navigation::GoalOutcome::kActive) {
    run.message = "timeout";
  } else if (!run.reached) {
    run.message = nav.message();
  }
}

}  // namespace

GoalRun driveUnknown(sim::Simulator& simulator, sensors::Scanner& scanner,
                     const std::string& tree_file, const robot::Pose2D& goal, std::uint32_t seed,
                     double timeout_s, double& clock, const exploration::KnownMap* known) {
  const world::World& world = simulator.world();
  world::RobotSpec robot = world.robot();
  robot.initial_pose = simulator.pose();
  behavior::RoombaParams params;
  params.rate = 1.0 / world.step;
  // No lag: the command of a pose moves the robot from that pose, as in the known world's runs.
  exploration::NavigateUnknown nav(robot, params, seed, 0.0, tree_file, known);
  nav.setGoal(goal);
  GoalRun run;
  run.start = robot.initial_pose;
  run.goal = goal;
  std::vector<robot::Pose2D> poses(1);
  driveGoal(simulator, nav, timeout_s, run,
            [&](const robot::BumperState& bumper, const robot::Pose2D& pose) {
              poses[0] = pose;
              for (const sensors::Scan& scan : scanner.scan(clock, poses)) {
                const sensors::RangeSensorSpec& spec = robot.sensors[scan.sensor];
                nav.addScan(mapping::mountedPose(pose, spec.mount),
                            mapping::scanView(spec, scan.ranges));
              }
              const robot::Velocity cmd = nav.tick(clock, bumper, pose, clock);
              clock += world.step;
              return cmd;
            });
  run.plans = nav.plans();
  return run;
}

NavEvalReport evaluateNavigation(const world::World& world, const std::string& tree_file,
                                 const NavEvalOptions& options,
                                 const std::function<void(int, int)>& progress) {
  NavEvalReport report;
  planning::Problem nav_world = world_planning::roomProblem(world);
  nav_world.clearance = options.clearance;
  planning::PlannerOptions planner_options = navigation::navPlannerOptions(nav_world);
  planner_options.seed = options.seed;
  const auto mode = options.threaded_planner ? navigation::InProcessPlanner::Mode::kThread
                                             : navigation::InProcessPlanner::Mode::kInline;
  navigation::NavLeafConfig config;
  std::vector<double>* times = &report.planning_ms;
  config.planners = [nav_world, planner_options, mode, times] {
    return std::make_unique<TimedPlanner>(
        std::make_unique<navigation::InProcessPlanner>(nav_world, planner_options, mode), *times);
  };
  navigation::InProcessPlanner::validate(nav_world, planner_options);
  config.known_world = std::make_shared<navigation::PathChecker>(nav_world);
  config.params.rate = 1.0 / world.step;
  config.follower.rate = config.params.rate;
  navigation::NavBt nav(config, options.seed, tree_file);
  sim::Simulator simulator(world);
  std::unique_ptr<sensors::Scanner> scanner;
  if (options.unknown) {
    if (world.robot().sensors.empty()) {
      throw util::InvalidInput("sensors",
                               "navigating an unknown world needs a range sensor on the robot (a "
                               "world file without `sensors:` has the lidar)");
    }
    scanner = std::make_unique<sensors::Scanner>(world);
  }
  std::optional<exploration::KnownMap> known;
  if (!options.known_map.empty()) {
    if (!options.unknown) {
      throw std::invalid_argument("a known map is for a robot that does not know the world");
    }
    known = exploration::loadKnownMap(options.known_map);
    exploration::checkKnownMap(*known, world.robot());  // before any goal: at the start
  }
  double clock = 0;  // robot s, on across the goals (the scanner's rate counts on it)
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> ux(world.room.origin.x,
                                            world.room.origin.x + world.room.width),
      uy(world.room.origin.y, world.room.origin.y + world.room.height), ut(-M_PI, M_PI);
  const double margin = world.robot().radius + options.clearance;

  for (int n = 0; n < options.goals; ++n) {
    GoalRun run;
    run.start = simulator.pose();
    for (int tries = 0; tries < 100000; ++tries) {
      const robot::Pose2D candidate{ux(rng), uy(rng), ut(rng)};
      if (!discFree(world, {candidate.x, candidate.y}, margin + 0.02)) continue;
      if (std::hypot(candidate.x - run.start.x, candidate.y - run.start.y) <
          options.min_goal_distance) {
        continue;
      }
      run.shortest_m = shortestDiscPathLength(world, run.start, candidate);
      if (!std::isfinite(run.shortest_m)) continue;
      run.goal = candidate;
      break;
    }
    if (options.unknown) {
      GoalRun driven = driveUnknown(simulator, *scanner, tree_file, run.goal,
                                    options.seed + static_cast<std::uint32_t>(n), options.timeout_s,
                                    clock, known ? &*known : nullptr);
      driven.shortest_m = run.shortest_m;
      run = std::move(driven);
    } else {
      nav.setGoal(run.goal);
      driveGoal(simulator, nav, options.timeout_s, run,
                [&](const robot::BumperState& bumper, const robot::Pose2D& pose) {
                  return nav.tick(bumper, pose);
                });
      if (nav.outcome() == navigation::GoalOutcome::kActive) nav.cancelGoal();
    }
    report.runs.push_back(std::move(run));
    if (progress) progress(n + 1, options.goals);
  }

  int reached = 0;
  double time_sum = 0, ratio_sum = 0;
  for (const GoalRun& run : report.runs) {
    report.bumps += run.bumps;
    if (!run.reached) continue;
    ++reached;
    time_sum += run.time_s;
    ratio_sum += run.shortest_m > 0 ? run.driven_m / run.shortest_m : 1.0;
  }
  const int total = static_cast<int>(report.runs.size());
  report.reached_pct = total ? 100.0 * reached / total : 0;
  report.mean_time_s = reached ? time_sum / reached : 0;
  report.mean_length_ratio = reached ? ratio_sum / reached : 0;
  report.planning_ms_p50 = median(report.planning_ms);
  return report;
}

std::string toJson(const NavEvalReport& r) {
  char text[512];
  std::snprintf(text, sizeof text,
                "{\"goals\": %zu, \"reached_pct\": %.2f, \"bumps\": %d, \"mean_time_s\": %.3f, "
                "\"mean_length_ratio\": %.4f, \"planning_ms_p50\": %.3f}",
                r.runs.size(), r.reached_pct, r.bumps, r.mean_time_s, r.mean_length_ratio,
                r.planning_ms_p50);
  return text;
}

}  // namespace roomba_rrt::tools
