// roomba_coverage: how much of the floor the lab's Roomba cleans, without ROS.
//
// Runs the simulation core with the FSM or the BT in one process, in the lab's step order
// (contact → bumper → behaviour → move), deterministic by seed. Prints the coverage at 60, 300
// and 600 s (mean ± standard deviation over seeds with --seeds), writes the first seed's
// trajectory as CSV and draws a typical run as a PNG (room, furniture, cleaned floor, path
// coloured by state): the seed whose final coverage is closest to the mean. Shows a progress bar
// on a terminal. With --robots N (or a world that names robots) several Roombas run the behaviour
// in one room, each its own, and the coverage is that of their union; --plot draws it over time
// for each N. See doc/behaviours.md and doc/simulation.md, "Several robots".
//
// Arguments: coverage_arguments.h; runs: coverage_run.h; statistics: coverage_statistics.h;
// pictures: coverage_drawing.h.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "coverage_arguments.h"
#include "coverage_drawing.h"
#include "coverage_run.h"
#include "coverage_statistics.h"
#include "progress_bar.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/statistics.h"
#include "roomba_rrt/world/world.h"
#include "tool_arguments.h"

namespace roomba_rrt::tools {
namespace {

using behavior::RoombaParams;

double secondsSince(std::chrono::steady_clock::time_point begin) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

/// --robots (or a world naming robots): every count × every seed, a table of union coverage, and
/// the plot.
int runFleets(const CoverageOptions& o, const world::World& world, const RoombaParams& params) {
  if (!o.csv.empty() || !o.png.empty()) {
    throw std::invalid_argument("--csv and --png draw one unnamed robot; " + o.world +
                                " names robots: use --plot");
  }
  std::vector<int> counts = o.robots;
  if (counts.empty()) counts.push_back(static_cast<int>(world.robots.size()));
  std::vector<FleetStatistics> fleets;
  ProgressBar progress(o.seeds * static_cast<int>(counts.size()), "runs");
  const auto begin = std::chrono::steady_clock::now();
  for (const int n : counts) {
    world::World fleet_world = world;
    if (!o.robots.empty()) fleet_world.robots = sim::spreadRobots(world, n);
    sim::MultiRobotSimulator simulator(fleet_world);
    FleetStatistics fleet;
    fleet.robots = n;
    fleet.at.resize(std::size(kCheckpoints));
    for (int i = 0; i < o.seeds; ++i) {
      const FleetRun result =
          simulateFleet(o, params, o.seed + static_cast<unsigned>(i), simulator);
      for (std::size_t c = 0; c < result.coverage_at.size(); ++c) {
        fleet.at[c].push_back(result.coverage_at[c]);
      }
      fleet.finals.push_back(result.final_coverage);
      fleet.curves.push_back(result.curve);
      progress.update(static_cast<int>(fleets.size()) * o.seeds + i + 1);
    }
    fleets.push_back(std::move(fleet));
  }
  const double seconds = secondsSince(begin);
  progress.finish(o.seeds * static_cast<int>(counts.size()));

  const std::string seeds =
      o.seeds > 1 ? "seeds " + std::to_string(o.seed) + "–" + std::to_string(o.seed + o.seeds - 1)
                  : "seed " + std::to_string(o.seed);
  std::printf("roomba_coverage: %s, %s, %.0f s of robot time per run, world %s\n",
              o.behavior.c_str(), seeds.c_str(), o.duration, o.world.c_str());
  std::printf("  floor cleaned by the robots together [%%]%s\n",
              o.seeds > 1 ? " (mean ± std)" : "");
  std::printf("  robots");
  for (std::size_t c = 0; c < std::size(kCheckpoints); ++c) {
    if (!fleets.front().at[c].empty()) std::printf("  %12.0f s", kCheckpoints[c]);
  }
  const bool final_is_checkpoint = finalIsCheckpoint(o.duration, world.step);
  if (!final_is_checkpoint) std::printf("  %12.0f s", o.duration);
  std::printf("\n");
  for (const FleetStatistics& fleet : fleets) {
    std::printf("  %6d", fleet.robots);
    for (const auto& values : fleet.at) {
      if (!values.empty()) std::printf("  %14s", percentMeanStd(values).c_str());
    }
    if (!final_is_checkpoint) std::printf("  %14s", percentMeanStd(fleet.finals).c_str());
    std::printf("\n");
  }
  std::printf("  simulated %zu × %d × %.0f s in %.3f s of wall time\n", counts.size(), o.seeds,
              o.duration, seconds);
  if (!o.plot.empty()) {
    const std::string title = std::string(o.behavior == "fsm" ? "FSM" : "BT") +
                              " on every robot in the room: floor cleaned together, mean ± std, " +
                              std::to_string(o.seeds) + (o.seeds == 1 ? " seed" : " seeds");
    drawCoveragePlot(o.plot, fleets, o.duration, title);
    std::printf("  plot: %s\n", o.plot.c_str());
  }
  return 0;
}

/// One unnamed robot: every seed, a table of coverage, the CSV of the first seed and the picture
/// of the typical one.
int runOne(const CoverageOptions& o, const world::World& world, const RoombaParams& params) {
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw std::runtime_error(o.csv + ": cannot write the CSV");
    csv.precision(10);
    csv << "t,x,y,theta,v,w,state,bumper\n";
  }

  sim::Simulator simulator(world);
  std::vector<std::vector<double>> at(std::size(kCheckpoints));
  std::vector<double> finals;
  ProgressBar progress(o.seeds, "runs");
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < o.seeds; ++i) {
    const Run result = simulate(o, params, o.seed + static_cast<unsigned>(i),
                                i == 0 && csv.is_open() ? &csv : nullptr, false, simulator);
    for (std::size_t c = 0; c < result.coverage_at.size(); ++c) {
      at[c].push_back(result.coverage_at[c]);
    }
    finals.push_back(result.final_coverage);
    progress.update(i + 1);
  }
  const double seconds = secondsSince(begin);
  progress.finish(o.seeds);

  // The picture: the typical run, simulated again (runs are deterministic by seed) with its path.
  const unsigned drawn_seed = o.seed + static_cast<unsigned>(closestToMean(finals));
  char title[200] = "";
  if (!o.png.empty()) {
    const Run drawn = simulate(o, params, drawn_seed, nullptr, true, simulator);
    const int n = std::snprintf(
        title, sizeof title, "%s, seed %u, %.0f s: %.1f %% of the floor cleaned",
        o.behavior == "fsm" ? "FSM" : "BT", drawn_seed, o.duration, 100 * drawn.final_coverage);
    if (o.seeds > 1) {
      std::snprintf(title + n, sizeof title - n, " (closest to the mean of seeds %u–%u, %.1f %%)",
                    o.seed, o.seed + o.seeds - 1, 100 * util::meanAndStd(finals).first);
    }
    drawRunPicture(o.png, simulator, drawn, title);
  }

  std::printf("roomba_coverage: %s, seed%s %u%s, %.0f s of robot time per run, world %s\n",
              o.behavior.c_str(), o.seeds > 1 ? "s" : "", o.seed,
              o.seeds > 1 ? ("–" + std::to_string(o.seed + o.seeds - 1)).c_str() : "", o.duration,
              o.world.c_str());
  std::printf("  time [s]   coverage [%%]%s\n", o.seeds > 1 ? " (mean ± std)" : "");
  for (std::size_t c = 0; c < at.size(); ++c) {
    if (!at[c].empty())
      std::printf("  %8.0f   %s\n", kCheckpoints[c], percentMeanStd(at[c]).c_str());
  }
  if (!finalIsCheckpoint(o.duration, world.step)) {
    std::printf("  %8.0f   %s\n", o.duration, percentMeanStd(finals).c_str());
  }
  std::printf("  simulated %d × %.0f s in %.3f s of wall time\n", o.seeds, o.duration, seconds);
  if (!o.csv.empty()) std::printf("  trajectory: %s\n", o.csv.c_str());
  if (!o.png.empty()) std::printf("  picture: %s, %s\n", o.png.c_str(), title);
  return 0;
}

int run(int argc, char** argv) {
  const CoverageOptions o = parseCoverageArguments(argc, argv);
  if (o.help) {
    std::fputs(coverageUsage(), stdout);
    return 0;
  }
  const world::World world = loadToolWorld(o.world, o.pose);
  RoombaParams params = behavior::loadRoombaParams(o.config);
  params.rate = 1.0 / world.step;  // one behaviour tick per simulation step, as in the lab
  if (!o.robots.empty() || !world.robots.empty()) return runFleets(o, world, params);
  if (!o.plot.empty()) throw std::invalid_argument("--plot needs --robots");
  return runOne(o, world, params);
}

}  // namespace
}  // namespace roomba_rrt::tools

int main(int argc, char** argv) {
  using roomba_rrt::tools::coverageUsage;
  try {
    return roomba_rrt::tools::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomba_coverage: %s\n%s", e.what(), coverageUsage());
    return 2;
  }
}
