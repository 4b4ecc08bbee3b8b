// Our RRT family against OMPL 1.5's on real occupancy maps (issue 17, item 6), in the same
// process with the same exact validity checker, and RRT* against the disc's shortest path.
//
//   map_comparison [--maps DIR]          every DIR/*.yaml (default: ../shared/maps), Markdown
//   map_comparison --maps DIR --json     the same figures as JSON (read by scripts/bench)
//   map_comparison --maps DIR --map willow_full --runs 3 --warmup 5 --budget-ms 100
//
// Per map: the robot is a disc of radius 0.17 m; occupied and unknown cells block. The pairs: 20
// lattice points (cell centres where the disc is free) of the largest region the disc can reach
// (bench/disc_lattice.h), drawn from std::mt19937 seeded 2024, each pair at least half the
// region's extent (its bounding box's diagonal) apart. Both sides get the planning library's
// CollisionChecker in `segments` mode: isFree for states, isSegmentFree (exact disc sweep against
// every blocked cell's square) for motions, OMPL through a MotionValidator that calls it
// (ompl_lab.h); the same range (20 cells), goal bias 0.05, goal tolerance 1e-3 and iteration cap;
// ours draws from the fast stream, as the service does on a map (doc/planning.md).
// RRT and RRT-Connect also face OMPL as a user sets it up: the same exact point check as its
// validity checker and OMPL's DiscreteMotionValidator at a quarter cell (`ompl_user`).
//   RRT, RRT-Connect   median CPU time per solve over pairs × runs, solved counts;
//   RRT*               path length after 100 ms of CPU time (OMPL: a termination condition on
//                      the thread's CPU clock; ours: the iterations that fit in 100 ms on that
//                      pair, measured first), each divided by the pair's shortest path
//                      (DiscLattice).
//   A* (issue 47)      the grid planner ROS users pick (navfn, global_planner, Smac 2D), as
//                      8-connected A* on the same inflated map (grid_astar.h): median CPU time
//                      per query (its inflated grid built once per map, timed apart), its length
//                      / shortest. Against it, our first path (RRT-Connect, above) and each
//                      route of kRoutes to a short path: how many of its paths are no longer
//                      than A*'s on the same pair, and its median CPU time.
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "arguments.h"
#include "disc_lattice.h"
#include "grid_astar.h"
#include "ompl_lab.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/planning/densify.h"
#include "roomba_rrt/planning/lab/scenarios.h"
#include "roomba_rrt/planning/planners/region_astar.h"

namespace {

using namespace roomba_rrt::bench;  // NOLINT: the measurement shared with ompl_comparison
namespace geometry = roomba_rrt::geometry;

constexpr double kRobotRadius = 0.17;  // m, the Roomba
constexpr double kStepCells = 20;      // the range, in cells of the map
constexpr double kGoalBias = 0.05;

struct Config {
  std::string maps_dir = ROOMBA_RRT_SHARED_MAPS;
  std::string only_map;  // --map NAME: that map alone
  int pairs = 20;
  int runs = 3;    // solves per pair and side, RRT and RRT-Connect
  int warmup = 5;  // untimed solves per side before them
  int star_runs = 1;
  double budget_s = 0.1;
  unsigned iterations = 200000;  // both sides' cap for RRT and RRT-Connect
  bool json = false;
  bool verbose = false;    // --verbose: each pair's time and length / A*'s on stderr
  bool grid_only = false;  // --grid-only: RRT, RRT-Connect and the A* rows (no RRT*)
  bool star = true;        // --no-star: RRT and RRT-Connect only (no RRT*, A* or shortest paths)
};

/// One side of a row: solved count, median CPU time, mean length and mean length / shortest.
struct Side {
  int solved = 0, runs = 0;
  double median_us = 0, mean_length = std::nan(""), mean_ratio = std::nan("");
  double min_ratio = std::nan("");  // the shortest found / the reference: ≥ 1 if both are right
  double median_work = 0;           // Solve::work: OMPL's motion checks, our iterations
};

struct Row {
  Side ours, ompl;
  Side ompl_user;  // OMPL with DiscreteMotionValidator at a quarter cell (RRT, RRT-Connect)
};

/// One way of ours to a short path, against the A* peer's length on each pair: how often its
/// path was no longer than A*'s, its median CPU time, and its mean length / A*'s.
struct ShortRoute {
  std::string name;
  int met = 0, runs = 0;
  double median_us = 0, mean_over_astar = std::nan("");
};

/// The grid planner's rows (grid_astar.h): the peer itself, then our routes to a path as short.
struct GridRows {
  double inflate_ms = 0;  // the peer's inflated grid (its edges), built once per map
  double regions_ms = 0;  // region_astar's GridRegions, built once per map
  Side astar;             // median CPU time per query, length / shortest
  double median_expanded = 0;
  std::vector<ShortRoute> routes;
};

struct MapRows {
  std::string name;
  int width = 0, height = 0;
  double resolution = 0, step = 0;
  int region_cells = 0;
  double shortest_mean = 0, shortest_seconds = 0;
  double sweep_ns = 0;  // CPU time of one isSegmentFree of a step from a free point
  Row rrt, rrt_connect, rrt_star;
  unsigned star_iterations = 0;  // our RRT*'s iterations in the budget, median over the pairs
  GridRows grid;
};

/// Runs solve(i) for i < warmup untimed, then `runs` times; lengths are divided by the shortest
/// path of pair i % shortest.size().
Side measureSide(int warmup, int runs, const std::vector<double>& shortest,
                 const std::function<Solve(int)>& solve) {
  for (int i = 0; i < warmup; ++i) solve(i);
  Side side;
  side.runs = runs;
  std::vector<double> seconds, work;
  double length_sum = 0, ratio_sum = 0;
  for (int i = 0; i < runs; ++i) {
    const Solve s = solve(warmup + i);
    seconds.push_back(s.seconds);
    work.push_back(static_cast<double>(s.work));
    if (!s.solved) continue;
    ++side.solved;
    length_sum += s.length;
    const double ratio = s.length / shortest[(warmup + i) % shortest.size()];
    ratio_sum += ratio;
    side.min_ratio = side.solved == 1 ? ratio : std::min(side.min_ratio, ratio);
  }
  side.median_us = median(seconds) * 1e6;
  side.median_work = median(work);
  if (side.solved > 0) {
    side.mean_length = length_sum / side.solved;
    side.mean_ratio = ratio_sum / side.solved;
  }
  return side;
}

/// The pairs (far apart in the largest region) and each one's shortest path length.
void drawPairs(const rp::Problem& base, const Config& cfg, std::vector<rp::Problem>& pairs,
               std::vector<double>& shortest, MapRows& rows) {
  const DiscLattice lattice(*base.map, kRobotRadius);
  const std::vector<int> region = lattice.largestComponent();
  rows.region_cells = static_cast<int>(region.size());
  if (region.size() < 2) throw std::runtime_error("no region the disc can move in");
  geometry::Point2 lo = lattice.centre(region.front()), hi = lo;
  for (int cell : region) {
    const geometry::Point2 c = lattice.centre(cell);
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
  }
  const double far_apart = 0.5 * geometry::distance(lo, hi);
  std::mt19937 random(2024);
  std::uniform_int_distribution<std::size_t> pick(0, region.size() - 1);
  const double t0 = threadCpuSeconds();
  while (static_cast<int>(pairs.size()) < cfg.pairs) {
    const int a = region[pick(random)], b = region[pick(random)];
    if (geometry::distance(lattice.centre(a), lattice.centre(b)) < far_apart) continue;
    rp::Problem p = base;
    p.start = lattice.centre(a);
    p.goal = lattice.centre(b);
    pairs.push_back(p);
    shortest.push_back(cfg.star ? geometry::pathLength(lattice.shortestPath(a, b)) : 1.0);
  }
  rows.shortest_seconds = cpuSecondsSince(t0) / cfg.pairs;
  for (double l : shortest) rows.shortest_mean += l / cfg.pairs;
}

/// The checker's cost as both sides pay it: CPU ns per isSegmentFree of one step, from a free
/// point (drawn as our sampler draws) in a random direction, averaged over 100 000 segments.
double sweepNanoseconds(const rp::Problem& base, double step) {
  const rp::CollisionChecker checker = rp::collisionChecker(base, rp::CollisionCheck::kSegments);
  const geometry::Rectangle e = base.map->grid().extent();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(e.min_x, e.max_x), y(e.min_y, e.max_y), turn(0, 6.283);
  std::vector<std::pair<geometry::Point2, geometry::Point2>> segments;
  while (segments.size() < 100000) {
    const geometry::Point2 a{x(random), y(random)};
    if (!checker.isFree(a)) continue;
    const double angle = turn(random);
    segments.push_back({a, {a.x + step * std::cos(angle), a.y + step * std::sin(angle)}});
  }
  int free = 0;
  const double t0 = threadCpuSeconds();
  for (const auto& [a, b] : segments) free += checker.isSegmentFree(a, b);
  const double seconds = cpuSecondsSince(t0);
  std::cerr << "  sweeps of " << step << " m: " << 100.0 * free / segments.size() << " % free\n";
  return seconds * 1e9 / segments.size();
}

template <typename OmplPlanner>
Row timeRow(const std::vector<rp::Problem>& pairs, const std::vector<double>& shortest,
            rp::PlannerOptions options, const Config& cfg) {
  std::vector<std::unique_ptr<OmplLab<OmplPlanner>>> ompl, ompl_user;
  const MotionCheck quarter_cell{0.25 * pairs.front().map->grid().resolution};
  for (const rp::Problem& q : pairs) {
    ompl.push_back(std::make_unique<OmplLab<OmplPlanner>>(q, options));
    ompl_user.push_back(std::make_unique<OmplLab<OmplPlanner>>(q, options, quarter_cell));
  }
  const int n = static_cast<int>(pairs.size());
  const int runs = n * cfg.runs;
  Row row;
  row.ompl = measureSide(cfg.warmup, runs, shortest,
                         [&](int i) { return ompl[i % n]->solve(cfg.iterations); });
  row.ompl_user = measureSide(cfg.warmup, runs, shortest,
                              [&](int i) { return ompl_user[i % n]->solve(cfg.iterations); });
  row.ours = measureSide(cfg.warmup, runs, shortest, [&](int i) {
    return solveOurs(pairs[i % n], options, cfg.iterations, 42u + static_cast<std::uint32_t>(i));
  });
  return row;
}

/// RRT*: OMPL's runs for the CPU-time budget; ours for the iterations that fit in it on each pair
/// (measured first: our planner stops by iterations). `median_iterations`: over the pairs.
Row starRow(const std::vector<rp::Problem>& pairs, const std::vector<double>& shortest,
            const rp::PlannerOptions& options, const Config& cfg, unsigned& median_iterations) {
  std::vector<std::unique_ptr<OmplLab<og::RRTstar>>> ompl;
  std::vector<unsigned> iterations;
  for (const rp::Problem& q : pairs) {
    ompl.push_back(std::make_unique<OmplLab<og::RRTstar>>(q, options));
    iterations.push_back(iterationsWithin(q, options, cfg.budget_s));
  }
  median_iterations =
      static_cast<unsigned>(median(std::vector<double>(iterations.begin(), iterations.end())));
  const int n = static_cast<int>(pairs.size());
  const int runs = n * cfg.star_runs;
  Row row;
  row.ompl =
      measureSide(0, runs, shortest, [&](int i) { return ompl[i % n]->solveFor(cfg.budget_s); });
  row.ours = measureSide(0, runs, shortest, [&](int i) {
    return solveOurs(pairs[i % n], options, iterations[i % n], 42u + static_cast<std::uint32_t>(i));
  });
  return row;
}

/// A way of ours to a short path: region_astar (planners/region_astar.h, make_plan's planner) on
/// the map's GridRegions (built once per map, timed apart as A*'s inflated grid is);
/// rrt_connect as make_plan planned before (RRT-Connect, exact segments, 0.5 m steps, 200 000
/// iterations, 200 shortcut tries) or RRT* at the map rows' range for a fixed number of
/// iterations, then, if `pull`, greedy string pulling over the path densified to 8 and then 2
/// cells (pullString(): each vertex joined to the farthest later one it sweeps freely to), every
/// pulled edge checked by the exact sweep.
struct RouteSpec {
  const char* name;
  rp::Algorithm algorithm;
  int iterations;
  bool pull;
  bool corridor = false;  // region_astar.h on the map's GridRegions, built once per map
};
constexpr RouteSpec kRoutes[] = {
    {"region_astar", rp::Algorithm::kRrtConnect, 0, false, true},
    {"rrt_connect", rp::Algorithm::kRrtConnect, 200000, false},
    {"rrt_connect+pull", rp::Algorithm::kRrtConnect, 200000, true},
    {"rrt_star_10k+pull", rp::Algorithm::kRrtStar, 10000, true},
};

/// The length of the route's path on `q` (NaN: none found).
double routeLength(const rp::Problem& q, std::uint32_t seed, const RouteSpec& route,
                   const rp::GridRegions& regions) {
  if (route.corridor) {
    const rp::PlanResult r = rp::solveRegionAStar(regions, q.start, q.goal);
    return r.success ? r.length : std::nan("");
  }
  const double cell = q.map->grid().resolution;
  rp::PlannerOptions o;
  o.algorithm = route.algorithm;
  o.collision = rp::CollisionCheck::kSegments;
  o.random_stream = rp::RandomStream::kFast;
  o.max_iterations = route.iterations;
  o.seed = seed;
  if (route.algorithm == rp::Algorithm::kRrtConnect) {
    o.step = 0.5;
    o.smooth = true;
    o.smoothing_tries = 200;
  } else {
    o.step = kStepCells * cell;
    o.goal_bias = kGoalBias;
  }
  rp::PlanResult r = rp::plan(q, o);
  if (!r.success) return std::nan("");
  if (!route.pull) return r.length;
  const rp::CollisionChecker checker = rp::collisionChecker(q, rp::CollisionCheck::kSegments);
  const auto sweep = [&checker](const rp::Point2& a, const rp::Point2& b) {
    return checker.isSegmentFree(a, b);
  };
  std::vector<rp::Point2> path = pullString(r.path, sweep);
  for (double d : {8 * cell, 2 * cell}) path = pullString(rp::densify(path, d), sweep);
  return rp::pathLength(path);
}

/// The A* peer on every pair (after building its inflated grid, timed apart), then each route of
/// ours, timed the same way, against A*'s length on the pair.
GridRows gridRows(const rp::Problem& base, const std::vector<rp::Problem>& pairs,
                  const std::vector<double>& shortest, const Config& cfg) {
  GridRows rows;
  const double t0 = threadCpuSeconds();
  const GridAStar astar(*base.map, kRobotRadius);
  rows.inflate_ms = cpuSecondsSince(t0) * 1e3;
  const rp::GridRegions regions(base.map, kRobotRadius);
  rows.regions_ms = regions.buildSeconds() * 1e3;
  std::cerr << "  regions: " << regions.regionCount() << " in " << rows.regions_ms << " ms, "
            << regions.bytes() / 1e6 << " MB\n";
  const int n = static_cast<int>(pairs.size());
  std::vector<double> astar_length(n, std::nan(""));
  rows.astar = measureSide(cfg.warmup, n * cfg.runs, shortest, [&](int i) {
    const rp::Problem& q = pairs[i % n];
    const double t = threadCpuSeconds();
    const GridAStar::Result r = astar.plan(q.start, q.goal);
    Solve s;
    s.seconds = cpuSecondsSince(t);
    s.solved = !r.path.empty();
    s.length = r.length;
    s.work = r.expanded;
    astar_length[i % n] = s.solved ? r.length : std::nan("");
    return s;
  });
  for (const RouteSpec& spec : kRoutes) {
    ShortRoute route;
    route.name = spec.name;
    std::vector<double> seconds;
    double ratio_sum = 0;
    int found = 0;
    for (int i = 0; i < cfg.warmup + n * cfg.runs; ++i) {
      const int pair = i % n;
      const double t = threadCpuSeconds();
      const double length =
          routeLength(pairs[pair], 42u + static_cast<std::uint32_t>(i), spec, regions);
      const double s = cpuSecondsSince(t);
      if (i < cfg.warmup) continue;
      if (cfg.verbose && i < cfg.warmup + n) {
        std::cerr << "    " << spec.name << " pair " << pair << ": " << s * 1e6 << " us, "
                  << length / astar_length[pair] << " x A*'s\n";
      }
      seconds.push_back(s);
      ++route.runs;
      if (!std::isfinite(length) || !std::isfinite(astar_length[pair])) continue;
      ++found;
      ratio_sum += length / astar_length[pair];
      if (length <= astar_length[pair] * (1 + 1e-9)) ++route.met;
    }
    route.median_us = median(seconds) * 1e6;
    if (found > 0) route.mean_over_astar = ratio_sum / found;
    std::cerr << "  " << spec.name << ": " << route.met << "/" << route.runs
              << " no longer than A*'s, " << route.median_us << " us (A* " << rows.astar.median_us
              << " us), length / A*'s " << route.mean_over_astar << "\n";
    rows.routes.push_back(route);
  }
  return rows;
}

MapRows runMap(const std::string& yaml, const Config& cfg) {
  MapRows rows;
  rows.name = std::filesystem::path(yaml).stem().string();
  auto grid = std::make_shared<const geometry::OccupancyGrid>(geometry::loadMap(yaml).grid);
  rows.width = grid->width;
  rows.height = grid->height;
  rows.resolution = grid->resolution;
  rp::Problem base = rp::mapProblem(grid);
  base.robot_radius = kRobotRadius;

  std::vector<rp::Problem> pairs;
  std::vector<double> shortest;
  drawPairs(base, cfg, pairs, shortest, rows);
  std::cerr << rows.name << ": " << pairs.size() << " pairs, shortest paths " << rows.shortest_mean
            << " m on average (" << rows.shortest_seconds * 1e3 << " ms each)\n";

  rp::PlannerOptions options;
  options.collision = rp::CollisionCheck::kSegments;
  options.random_stream = rp::RandomStream::kFast;  // as the service plans on a map (scenario map)
  options.step = kStepCells * grid->resolution;
  options.goal_bias = kGoalBias;
  rows.step = options.step;
  rows.sweep_ns = sweepNanoseconds(base, options.step);
  options.algorithm = rp::Algorithm::kRrt;
  rows.rrt = timeRow<og::RRT>(pairs, shortest, options, cfg);
  options.algorithm = rp::Algorithm::kRrtConnect;
  rows.rrt_connect = timeRow<og::RRTConnect>(pairs, shortest, options, cfg);
  options.algorithm = rp::Algorithm::kRrtStar;
  if (!cfg.star) return rows;
  rows.grid = gridRows(base, pairs, shortest, cfg);
  std::cerr << rows.name << ": A* " << rows.grid.astar.median_us << " us (inflated grid "
            << rows.grid.inflate_ms << " ms), length / shortest " << rows.grid.astar.mean_ratio
            << "\n";
  if (cfg.grid_only) return rows;
  rows.rrt_star = starRow(pairs, shortest, options, cfg, rows.star_iterations);
  std::cerr << rows.name << ": RRT " << rows.rrt.ours.median_us << " / " << rows.rrt.ompl.median_us
            << " / " << rows.rrt.ompl_user.median_us << " us, RRT-Connect "
            << rows.rrt_connect.ours.median_us << " / " << rows.rrt_connect.ompl.median_us << " / "
            << rows.rrt_connect.ompl_user.median_us << " us (ours / OMPL / OMPL user checker)"
            << ", RRT* length / shortest " << rows.rrt_star.ours.mean_ratio << " / "
            << rows.rrt_star.ompl.mean_ratio << "\n";
  return rows;
}

// ---------------------------------------------------------------------------------------------
// Output.

std::string sideJson(const Side& s) {
  return "{\"solved\": " + std::to_string(s.solved) + ", \"runs\": " + std::to_string(s.runs) +
         ", \"median_us\": " + num(s.median_us, 2) + ", \"mean_length\": " + num(s.mean_length, 4) +
         ", \"mean_length_over_shortest\": " + num(s.mean_ratio, 4) +
         ", \"min_length_over_shortest\": " + num(s.min_ratio, 4) +
         ", \"median_work\": " + num(s.median_work, 0) + "}";
}

std::string gridJson(const GridRows& g) {
  std::string routes;
  for (const ShortRoute& r : g.routes) {
    routes += std::string(routes.empty() ? "" : ", ") + "{\"route\": \"" + r.name +
              "\", \"met\": " + std::to_string(r.met) + ", \"runs\": " + std::to_string(r.runs) +
              ", \"median_us\": " + num(r.median_us, 2) +
              ", \"mean_length_over_astar\": " + num(r.mean_over_astar, 4) + "}";
  }
  return "{\"inflate_ms\": " + num(g.inflate_ms, 2) + ", \"regions_ms\": " + num(g.regions_ms, 2) +
         ", \"astar\": " + sideJson(g.astar) + ", \"routes\": [" + routes + "]}";
}

std::string rowJson(const Row& r) {
  return "{\"ours\": " + sideJson(r.ours) + ", \"ompl\": " + sideJson(r.ompl) +
         ", \"ompl_user\": " + sideJson(r.ompl_user) + "}";
}

void printJson(const std::vector<MapRows>& maps, const Config& cfg) {
  std::cout << "{\"ompl_version\": \"" << kOmplVersion << "\", \"robot_radius\": " << kRobotRadius
            << ", \"pairs\": " << cfg.pairs << ", \"runs_per_pair\": " << cfg.runs
            << ", \"budget_ms\": " << num(cfg.budget_s * 1e3, 1) << ",\n \"maps\": [\n";
  for (std::size_t k = 0; k < maps.size(); ++k) {
    const MapRows& m = maps[k];
    std::cout << "  {\"map\": \"" << m.name << "\", \"width\": " << m.width
              << ", \"height\": " << m.height << ", \"resolution\": " << m.resolution
              << ", \"step\": " << num(m.step, 3) << ", \"region_cells\": " << m.region_cells
              << ", \"shortest_mean_length\": " << num(m.shortest_mean, 3)
              << ", \"shortest_ms\": " << num(m.shortest_seconds * 1e3, 1)
              << ", \"star_iterations\": " << m.star_iterations
              << ", \"sweep_ns\": " << num(m.sweep_ns, 1) << ",\n   \"rrt\": " << rowJson(m.rrt)
              << ",\n   \"rrt_connect\": " << rowJson(m.rrt_connect)
              << ",\n   \"rrt_star\": " << rowJson(m.rrt_star)
              << ",\n   \"grid\": " << gridJson(m.grid) << "}" << (k + 1 < maps.size() ? "," : "")
              << "\n";
  }
  std::cout << " ]}\n";
}

void printMarkdown(const std::vector<MapRows>& maps, const Config& cfg) {
  std::cout << "Maps, disc radius " << kRobotRadius << " m, segments, range 20 cells, goal bias "
            << kGoalBias << ", " << cfg.pairs << " pairs x " << cfg.runs
            << " (RRT, RRT-Connect: median CPU time; RRT*: length / shortest after "
            << cfg.budget_s * 1e3 << " ms)\n\n"
            << "| map | shortest m | RRT µs ours | OMPL | ours/OMPL | OMPL user | ours/user | "
               "solved | RRT-Connect µs ours | OMPL | ours/OMPL | OMPL user | ours/user | solved "
               "| RRT* L/shortest ours | OMPL | solved |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  auto solved = [](const Row& r) {
    return std::to_string(r.ours.solved) + "/" + std::to_string(r.ompl.solved) + " of " +
           std::to_string(r.ours.runs);
  };
  auto times = [](const Row& r) {  // ours, OMPL, ratio, OMPL with the user's checker, ratio
    return num(r.ours.median_us, 1) + " | " + num(r.ompl.median_us, 0) + " | " +
           num(r.ours.median_us / r.ompl.median_us, 3) + " | " + num(r.ompl_user.median_us, 0) +
           " | " + num(r.ours.median_us / r.ompl_user.median_us, 3) + " | ";
  };
  for (const MapRows& m : maps) {
    std::cout << "| " << m.name << " | " << num(m.shortest_mean, 1) << " | " << times(m.rrt)
              << solved(m.rrt) << " | " << times(m.rrt_connect) << solved(m.rrt_connect) << " | "
              << num(m.rrt_star.ours.mean_ratio, 3) << " | " << num(m.rrt_star.ompl.mean_ratio, 3)
              << " | " << solved(m.rrt_star) << " |\n";
  }
  std::cout << "\nAgainst 8-connected A* on the inflated grid (bench/grid_astar.h): median CPU time"
               " per query; a short path: paths no longer than A*'s on the same pair\n\n"
               "| map | A* µs | A* L/shortest | RRT-Connect first µs | /A* |";
  for (const RouteSpec& r : kRoutes) std::cout << " " << r.name << " µs | as short | L/A* |";
  std::cout << "\n|---|---|---|---|---|";
  for (std::size_t k = 0; k < std::size(kRoutes); ++k) std::cout << "---|---|---|";
  std::cout << "\n";
  for (const MapRows& m : maps) {
    const GridRows& g = m.grid;
    std::cout << "| " << m.name << " | " << num(g.astar.median_us, 0) << " | "
              << num(g.astar.mean_ratio, 3) << " | " << num(m.rrt_connect.ours.median_us, 0)
              << " | " << num(m.rrt_connect.ours.median_us / g.astar.median_us, 3) << " |";
    for (const ShortRoute& r : g.routes) {
      std::cout << " " << num(r.median_us, 0) << " | " << r.met << "/" << r.runs << " | "
                << num(r.mean_over_astar, 3) << " |";
    }
    std::cout << "\n";
  }
}

// ---------------------------------------------------------------------------------------------
// Command line.

const char* const kUsage =
    "usage: map_comparison [--maps DIR] [--map NAME] [--json] [--pairs N] [--runs N]"
    " [--warmup N] [--star-runs N] [--budget-ms MS] [--iterations N] [--grid-only | --no-star]\n"
    "  every DIR/*.yaml (default: ../shared/maps beside the repository)\n"
    "  --grid-only: RRT, RRT-Connect and the A* rows, without RRT*\n"
    "  --no-star: RRT and RRT-Connect alone (no shortest paths, A* or RRT*)\n";

Config parseArgs(int argc, char** argv) {
  Config cfg;
  roomba_rrt::bench::Arguments args(argc, argv, "map_comparison", kUsage);
  while (args.next()) {
    if (args.is("--json")) {
      cfg.json = true;
    } else if (args.is("--maps")) {
      cfg.maps_dir = args.value();
    } else if (args.is("--verbose")) {
      cfg.verbose = true;
    } else if (args.is("--grid-only")) {
      cfg.grid_only = true;
    } else if (args.is("--map")) {
      cfg.only_map = args.value();
    } else if (args.is("--pairs")) {
      cfg.pairs = args.count(1);
    } else if (args.is("--runs")) {
      cfg.runs = args.count(1);
    } else if (args.is("--warmup")) {
      cfg.warmup = args.count();
    } else if (args.is("--star-runs")) {
      cfg.star_runs = args.count(1);
    } else if (args.is("--budget-ms")) {
      cfg.budget_s = args.count(1) * 1e-3;
    } else if (args.is("--no-star")) {
      cfg.star = false;
    } else if (args.is("--iterations")) {
      cfg.iterations = static_cast<unsigned>(args.count(1));
    } else {
      args.unknown();
    }
  }
  return cfg;
}

}  // namespace

int main(int argc, char** argv) {
  const Config cfg = parseArgs(argc, argv);
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  ompl::RNG::setSeed(42);  // before any planner exists: OMPL seeds every RNG from this one
  g_clock_overhead = clockOverhead();

  std::vector<std::string> files;
  std::error_code error;
  if (!std::filesystem::is_directory(cfg.maps_dir, error)) {
    roomba_rrt::bench::exitWithUsage(
        "map_comparison",
        "--maps: '" + cfg.maps_dir + "' is not a directory (" +
            (error ? error.message() : std::string("missing or a file")) +
            "); the real maps are in shared/maps beside the repository (doc/testing.md)",
        kUsage);
  }
  for (const auto& entry : std::filesystem::directory_iterator(cfg.maps_dir)) {
    const auto& p = entry.path();
    if (p.extension() == ".yaml" && (cfg.only_map.empty() || p.stem() == cfg.only_map)) {
      files.push_back(p.string());
    }
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    roomba_rrt::bench::exitWithUsage("map_comparison", "no map YAML in " + cfg.maps_dir, kUsage);
  }
  std::vector<MapRows> maps;
  for (const std::string& file : files) {
    try {
      maps.push_back(runMap(file, cfg));
    } catch (const std::exception& e) {
      std::cerr << "map_comparison: " << file << ": " << e.what() << "\n";
      return 1;
    }
  }
  cfg.json ? printJson(maps, cfg) : printMarkdown(maps, cfg);
  return 0;
}
