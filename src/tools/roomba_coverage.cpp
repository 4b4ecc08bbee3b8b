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
#include <cmath>
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
#include "roomba_rrt/sensors/range_sensor.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/util/statistics.h"
#include "roomba_rrt/world/world.h"
#include "tool_arguments.h"

namespace roomba_rrt::tools {
namespace {

/// The world as the header names it: its file, and the region --crop kept (whole cells inside
/// the region asked: up to a cell smaller, world::cropped).
std::string worldLabel(const CoverageArguments& o, const world::World& world) {
  if (o.crop.empty()) return o.world;
  char region[160];
  std::snprintf(region, sizeof region, " cut to (%.6g, %.6g) to (%.6g, %.6g)", world.room.origin.x,
                world.room.origin.y, world.room.origin.x + world.room.width,
                world.room.origin.y + world.room.height);
  return o.world + region;
}

using behavior::RoombaParams;

double secondsSince(std::chrono::steady_clock::time_point begin) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

/// --robots (or a world naming robots): every count × every seed, a table of union coverage, and
/// the plot.
int runFleets(const CoverageArguments& o, const world::World& world, const RoombaParams& params) {
  if (!o.csv.empty() || !o.png.empty()) {
    throw std::invalid_argument("--csv and --png draw one unnamed robot; " + o.world +
                                " names robots: use --plot");
  }
  if (o.lag > 0) throw std::invalid_argument("--lag simulates one unnamed robot, no fleet");
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
              o.behavior.c_str(), seeds.c_str(), o.duration, worldLabel(o, world).c_str());
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
int runOne(const CoverageArguments& o, const world::World& world, const RoombaParams& params) {
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
              worldLabel(o, world).c_str());
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

/// Seconds as "mean ± std" over the runs that got there; "(k/n)" when only k of n did, "—" when
/// none did (NaN: not reached).
std::string secondsMeanStd(const std::vector<double>& values) {
  std::vector<double> reached;
  for (double v : values) {
    if (!std::isnan(v)) reached.push_back(v);
  }
  if (reached.empty()) return "—";
  const auto [mean, std] = util::meanAndStd(reached);
  char text[64];
  if (reached.size() < values.size()) {
    std::snprintf(text, sizeof text, "%.0f (%zu/%zu)", mean, reached.size(), values.size());
  } else if (values.size() < 2) {
    std::snprintf(text, sizeof text, "%.0f", mean);
  } else {
    std::snprintf(text, sizeof text, "%.0f ± %.0f", mean, std);
  }
  return text;
}

std::string countMeanStd(const std::vector<double>& values) {
  const auto [mean, std] = util::meanAndStd(values);
  char text[64];
  if (values.size() < 2) {
    std::snprintf(text, sizeof text, "%.0f", mean);
  } else {
    std::snprintf(text, sizeof text, "%.1f ± %.1f", mean, std);
  }
  return text;
}

/// `text` aligned in `width` characters (UTF-8: "±" and "—" are one character, not two or
/// three bytes as printf's width counts them).
std::string padding(const std::string& text, std::size_t width) {
  std::size_t characters = 0;
  for (const char c : text) characters += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return std::string(width > characters ? width - characters : 0, ' ');
}
std::string rightAligned(const std::string& text, std::size_t width) {
  return padding(text, width) + text;
}
std::string leftAligned(const std::string& text, std::size_t width) {
  return text + padding(text, width);
}

/// One behaviour's runs on the reachable floor, [measure][seed].
struct ReachableStatistics {
  std::string behavior;
  std::vector<std::vector<double>> at, at_ideal, time_to;
  std::vector<double> finals, bumps;
  std::vector<double> explored;  ///< unknown: when exploring ended (s)
  std::vector<double> plans;     ///< known-map: plans made per run
  std::vector<double> done;      ///< unknown by touch: when no move was left (s)
  bool by_touch = false;
  std::vector<std::vector<double>> curves;
};

/// --behavior coverage (one column) or --compare (fsm, bt and coverage): the coverage of the
/// reachable floor (the floor cells the disc swept, over the coverage planner's reachable area)
/// at the checkpoints and at 1.5×, 2× and 2.5× the ideal time, the time to 90 / 95 / 99 % of it and
/// the bumps per run, one column per behaviour; coverage's CSV and picture; --plot: the curves.
int runReachable(const CoverageArguments& options, const world::World& world,
                 const RoombaParams& params, const std::vector<std::string>& behaviors) {
  std::ofstream csv;
  if (!options.csv.empty()) {
    csv.open(options.csv);
    if (!csv) throw std::runtime_error(options.csv + ": cannot write the CSV");
    csv.precision(10);
    csv << "t,x,y,theta,v,w,state,bumper\n";
  }
  const Cleaning cleaning(world, params);
  sim::Simulator simulator(world);
  std::vector<ReachableStatistics> columns;
  ProgressBar progress(options.seeds * static_cast<int>(behaviors.size()), "runs");
  const auto begin = std::chrono::steady_clock::now();
  for (const std::string& behavior : behaviors) {
    CoverageArguments o = options;
    o.behavior = behavior;
    ReachableStatistics column;
    column.behavior = behavior;
    column.at.resize(std::size(kCheckpoints));
    column.at_ideal.resize(std::size(kIdealMultiples));
    column.time_to.resize(std::size(kTargets));
    for (int i = 0; i < o.seeds; ++i) {
      const Run result =
          simulate(o, params, o.seed + static_cast<unsigned>(i),
                   i == 0 && csv.is_open() ? &csv : nullptr, false, simulator, &cleaning);
      for (std::size_t c = 0; c < result.reachable_at.size(); ++c) {
        column.at[c].push_back(result.reachable_at[c]);
      }
      for (std::size_t m = 0; m < result.at_ideal.size(); ++m) {
        column.at_ideal[m].push_back(result.at_ideal[m]);
      }
      for (std::size_t t = 0; t < result.time_to.size(); ++t) {
        column.time_to[t].push_back(result.time_to[t]);
      }
      column.finals.push_back(result.reachable_final);
      column.bumps.push_back(result.bumps);
      if (behavior == "unknown") column.explored.push_back(result.explored_at);
      if (behavior == "known-map") column.plans.push_back(result.plans);
      if (result.by_touch) column.done.push_back(result.done_at);
      column.by_touch = result.by_touch;
      column.curves.push_back(result.curve);
      progress.update(static_cast<int>(columns.size()) * o.seeds + i + 1);
    }
    columns.push_back(std::move(column));
  }
  const double seconds = secondsSince(begin);
  progress.finish(options.seeds * static_cast<int>(behaviors.size()));

  char title[200] = "";
  if (!options.png.empty()) {
    const unsigned drawn_seed =
        options.seed + static_cast<unsigned>(closestToMean(columns.front().finals));
    CoverageArguments o = options;
    o.behavior = behaviors.front();
    const Run drawn = simulate(o, params, drawn_seed, nullptr, true, simulator, &cleaning);
    std::snprintf(title, sizeof title,
                  "%s, seed %u, %.0f s: %.1f %% of the reachable floor cleaned, %d bumps",
                  o.behavior.c_str(), drawn_seed, o.duration, 100 * drawn.reachable_final,
                  drawn.bumps);
    drawRunPicture(options.png, simulator, drawn, title);
  }

  const int n = options.seeds;
  const std::string seeds =
      n > 1 ? "seeds " + std::to_string(options.seed) + "–" + std::to_string(options.seed + n - 1)
            : "seed " + std::to_string(options.seed);
  std::string names;
  for (std::size_t b = 0; b < behaviors.size(); ++b) {
    names += (b == 0 ? "" : b + 1 == behaviors.size() ? " and " : ", ") + behaviors[b];
  }
  std::printf("roomba_coverage: %s, %s, %.0f s of robot time per run, world %s\n", names.c_str(),
              seeds.c_str(), options.duration, worldLabel(options, world).c_str());
  if (options.unknown && columns.back().by_touch) {
    std::printf(
        "  unknown: the robot starts with an empty map, its bumper and IR light bumper (no "
        "lidar): online boustrophedon\n");
  } else if (options.unknown && options.known_map.empty()) {
    std::printf(
        "  unknown: the robot starts with an empty map and its lidar, explores, then cleans\n");
  } else if (options.unknown) {
    std::printf(
        "  known-map: the robot is given %s and its lidar; it plans on the map at once and again\n"
        "  when its scans show the rest blocked\n",
        options.known_map.c_str());
  }
  std::printf(
      "  reachable floor %.2f m² of %.2f m² of floor (the coverage planner's, from the "
      "start); ideal time %.1f s\n",
      cleaning.reachable_area, cleaning.floor_area, cleaning.ideal_time);
  std::printf("  coverage of the reachable floor [%%]%s\n", n > 1 ? " (mean ± std)" : "");
  std::printf("  %s", leftAligned("time [s]", 22).c_str());
  for (const ReachableStatistics& column : columns) {
    std::printf("  %s", rightAligned(column.behavior, 14).c_str());
  }
  std::printf("\n");
  const auto row = [&columns](const std::string& label, const auto& cell) {
    std::printf("  %s", leftAligned(label, 22).c_str());
    for (const ReachableStatistics& column : columns) {
      std::printf("  %s", rightAligned(cell(column), 14).c_str());
    }
    std::printf("\n");
  };
  char label[64];
  // The checkpoints and the ideal time's multiples, in the order of time.
  std::size_t c = 0, m = 0;
  while (c < std::size(kCheckpoints) || m < std::size(kIdealMultiples)) {
    const bool ideal = m < std::size(kIdealMultiples) &&
                       (c == std::size(kCheckpoints) ||
                        kIdealMultiples[m] * cleaning.ideal_time < kCheckpoints[c]);
    const std::vector<double>& first = ideal ? columns.front().at_ideal[m] : columns.front().at[c];
    if (!first.empty()) {
      if (ideal) {
        std::snprintf(label, sizeof label, "%8.0f (%.1f× ideal)",
                      kIdealMultiples[m] * cleaning.ideal_time, kIdealMultiples[m]);
      } else {
        std::snprintf(label, sizeof label, "%8.0f", kCheckpoints[c]);
      }
      row(label, [&](const ReachableStatistics& s) {
        return percentMeanStd(ideal ? s.at_ideal[m] : s.at[c]);
      });
    }
    (ideal ? m : c) += 1;
  }
  if (!finalIsCheckpoint(options.duration, world.step)) {
    std::snprintf(label, sizeof label, "%8.0f", options.duration);
    row(label, [](const ReachableStatistics& s) { return percentMeanStd(s.finals); });
  }
  for (std::size_t t = 0; t < std::size(kTargets); ++t) {
    std::snprintf(label, sizeof label, "time to %.0f %% [s]", 100 * kTargets[t]);
    row(label, [t](const ReachableStatistics& s) { return secondsMeanStd(s.time_to[t]); });
  }
  row("bumps per run", [](const ReachableStatistics& s) { return countMeanStd(s.bumps); });
  if (options.unknown && columns.back().by_touch) {
    row("done at [s]", [](const ReachableStatistics& s) {
      return s.done.empty() ? std::string("—") : secondsMeanStd(s.done);
    });
  } else if (options.unknown && options.known_map.empty()) {
    row("explored by [s]", [](const ReachableStatistics& s) {
      return s.explored.empty() ? std::string("—") : secondsMeanStd(s.explored);
    });
  } else if (options.unknown) {
    row("plans per run", [](const ReachableStatistics& s) {
      return s.plans.empty() ? std::string("—") : countMeanStd(s.plans);
    });
  }
  std::printf("  simulated %zu × %d × %.0f s in %.3f s of wall time\n", behaviors.size(), n,
              options.duration, seconds);
  if (!options.csv.empty()) std::printf("  trajectory: %s\n", options.csv.c_str());
  if (!options.png.empty()) std::printf("  picture: %s, %s\n", options.png.c_str(), title);
  if (!options.plot.empty()) {
    std::vector<FleetStatistics> curves;
    for (const ReachableStatistics& column : columns) {
      FleetStatistics curve;
      curve.robots = 1;
      curve.label = column.behavior;
      curve.at = column.at;
      curve.finals = column.finals;
      curve.curves = column.curves;
      curves.push_back(std::move(curve));
    }
    drawCoveragePlot(
        options.plot, curves, options.duration,
        "Reachable floor cleaned, mean ± std, " + std::to_string(n) + (n == 1 ? " seed" : " seeds"),
        "reachable floor cleaned");
    std::printf("  plot: %s\n", options.plot.c_str());
  }
  return 0;
}

int run(int argc, char** argv) {
  const CoverageArguments o = parseCoverageArguments(argc, argv);
  if (o.help) {
    std::fputs(coverageUsage(), stdout);
    return 0;
  }
  world::World world = loadToolWorld(o.world, o.pose, o.crop);
  if (o.sensors) {  // presets on the robot in place of the world file's sensors
    std::vector<sensors::RangeSensorSpec> specs;
    for (const std::string& name : *o.sensors) {
      specs.push_back(sensors::preset(name, world.robot().radius, "--sensors"));
    }
    sensors::validate(specs, "--sensors", world.robot().radius, world.step);
    world.robot().sensors = specs;
  }
  RoombaParams params = behavior::loadRoombaParams(o.config);
  params.rate = 1.0 / world.step;  // one behaviour tick per simulation step, as in the lab
  const std::string unknown = o.known_map.empty() ? "unknown" : "known-map";
  if (o.compare && o.unknown) {
    return runReachable(o, world, params, {"fsm", "bt", "coverage", unknown});
  }
  if (o.compare) return runReachable(o, world, params, {"fsm", "bt", "coverage"});
  if (o.behavior == "coverage") {
    return runReachable(o, world, params, {o.unknown ? unknown : "coverage"});
  }
  if (!o.robots.empty() || world.namedRobots()) return runFleets(o, world, params);
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
