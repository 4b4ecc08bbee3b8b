// The mapper (mapping/occupancy_mapper.h) measured two ways:
//
//   accuracy  one cleaning run (the coverage tree, config/roomba_coverage_tree.xml, for 2.5× the
//             ideal time) of the furnished room and of a 60 m² crop of willow_full, with the
//             simulator core, its LDS (scanner.h) and the bumper feeding the mapper in process;
//             then every cell the sensor saw is compared with the true world (map_accuracy.h):
//             the share that agrees (target ≥ 99 %) and the occupied cells with no obstacle
//             within one cell (target 0);
//   update    the CPU time of one 360-ray LDS scan (3.5 m) added to a grid of 1000 × 1000 cells
//             (0.05 m) over willow_full, from random free poses (target ≤ 1 ms); and, when built
//             with MRPT (libmrpt-maps-dev), the same scans inserted into MRPT's
//             COccupancyGridMap2D of the same size and resolution.
//
//   mapping_bench [--json] [--scans 4000] [--maps DIR]
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "arguments.h"
#include "coverage_run.h"
#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/mapping/map_accuracy.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/mapping/sensor_scan.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/world/world_file.h"
#include "tool_arguments.h"

#ifdef ROOMBA_RRT_WITH_MRPT
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#endif

namespace {

using namespace roomba_rrt;

constexpr const char* kUsage =
    "usage: mapping_bench [--json] [--scans N] [--maps DIR]\n"
    "  the mapper's agreement with the true world after one cleaning run (furnished room, a\n"
    "  willow_full crop) and the CPU time of one 360-ray scan update on a 10^6-cell grid\n";

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct AccuracyRow {
  std::string world;
  mapping::MapAccuracy accuracy;
  double seconds = 0;   ///< simulated
  double coverage = 0;  ///< of the reachable floor
  int bumps = 0;
  std::size_t scans = 0;
  bool with_mrpt = false;
  mapping::MapAccuracy mrpt;  ///< MRPT's grid fed the same scans, when built with it
};

#ifdef ROOMBA_RRT_WITH_MRPT
/// A scan of `spec` as MRPT's CObservation2DRangeScan: MRPT's ray k is at −a/2 + k a / (n − 1)
/// from the sensor's heading (a = angle_max − angle_min), so the sensor is turned by angle_min +
/// a/2; no return (+inf) is an invalid ray, which MRPT clears up to maxRange as REP 117 says.
mrpt::obs::CObservation2DRangeScan mrptScan(const sensors::RangeSensorSpec& spec,
                                            const std::vector<float>& ranges) {
  mrpt::obs::CObservation2DRangeScan o;
  const double aperture = spec.angle_max - spec.angle_min;
  o.aperture = static_cast<float>(aperture);
  o.rightToLeft = true;
  o.maxRange = static_cast<float>(spec.range_max);
  o.sensorPose = mrpt::poses::CPose3D(0, 0, 0, spec.angle_min + aperture / 2, 0, 0);
  o.resizeScan(ranges.size());
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const bool valid = std::isfinite(ranges[r]);
    o.setScanRange(r, valid ? ranges[r] : o.maxRange);
    o.setScanRangeValidity(r, valid);
  }
  return o;
}

/// MRPT's grid over `region` at its resolution, inserting up to `range_max`.
mrpt::maps::COccupancyGridMap2D mrptGrid(const mapping::MapperOptions& region, double range_max) {
  mrpt::maps::COccupancyGridMap2D map(region.xmin, region.xmax, region.ymin, region.ymax,
                                      static_cast<float>(region.resolution));
  map.insertionOptions.maxDistanceInsertion = static_cast<float>(range_max);
  map.insertionOptions.considerInvalidRangesAsFreeSpace = true;
  return map;
}

mrpt::poses::CPose3D mrptPose(const robot::Pose2D& p) {
  return mrpt::poses::CPose3D(p.x, p.y, 0, p.theta, 0, 0);
}

/// MRPT's cells as nav_msgs' trinary ones. MRPT keeps the log-odds of being free: 0 unknown,
/// above free, below occupied.
geometry::OccupancyGrid trinary(const mrpt::maps::COccupancyGridMap2D& map) {
  geometry::OccupancyGrid grid;
  grid.width = static_cast<int>(map.getSizeX());
  grid.height = static_cast<int>(map.getSizeY());
  grid.resolution = map.getResolution();
  grid.origin = {map.getXMin(), map.getYMin()};
  for (int j = 0; j < grid.height; ++j) {
    const auto* row = map.getRow(j);
    for (int i = 0; i < grid.width; ++i) {
      grid.cells.push_back(row[i] == 0  ? geometry::OccupancyGrid::kUnknown
                           : row[i] > 0 ? geometry::OccupancyGrid::kFree
                                        : geometry::OccupancyGrid::kOccupied);
    }
  }
  return grid;
}
#endif

/// One cleaning run of `world` with its first robot's sensors (the LDS when it has none) and
/// its bumper feeding a mapper of 0.05 m cells over the room.
AccuracyRow cleaningRun(const std::string& label, world::World world) {
  if (world.robot().sensors.empty()) world.robot().sensors = {sensors::ldsPreset()};
  behavior::RoombaParams params =
      behavior::loadRoombaParams(ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml");
  params.rate = 1.0 / world.step;  // one tick per step, as roomba_coverage
  const tools::Cleaning cleaning(world, params);
  navigation::NavBt tree(cleaning.config, 1, ROOMBA_RRT_CONFIG_DIR "/roomba_coverage_tree.xml");
  sim::Simulator simulator(world);
  sensors::Scanner scanner(world);
  mapping::MapperOptions options;
  options.xmin = world.room.origin.x;
  options.ymin = world.room.origin.y;
  options.xmax = options.xmin + world.room.width;
  options.ymax = options.ymin + world.room.height;
  mapping::OccupancyMapper mapper(options);
  const world::RobotSpec& robot = world.robot();
#ifdef ROOMBA_RRT_WITH_MRPT
  mapping::MapperOptions region = options;  // MRPT's grid does not grow: the walls' cells too
  region.xmin -= 0.5;
  region.ymin -= 0.5;
  region.xmax += 0.5;
  region.ymax += 0.5;
  mrpt::maps::COccupancyGridMap2D mrpt_map = mrptGrid(region, robot.sensors.front().range_max);
#endif
  AccuracyRow row;
  row.world = label;
  const long steps = std::lround(2.5 * cleaning.ideal_time / world.step);
  bool was_pressed = simulator.senseContact().pressed;
  std::vector<robot::Pose2D> poses(1);
  // The lab's step order (tools::simulate): contact and bumper, sensing, behaviour, move.
  for (long k = 0; k < steps; ++k) {
    const robot::BumperState bumper = simulator.senseContact();
    row.bumps += bumper.pressed && !was_pressed;
    was_pressed = bumper.pressed;
    poses[0] = simulator.pose();
    for (const sensors::Scan& scan : scanner.scan(simulator.time(), poses)) {
      const sensors::RangeSensorSpec& spec = robot.sensors[scan.sensor];
      const robot::Pose2D at = mapping::mountedPose(poses[0], spec.mount);
      mapper.addScan(at, mapping::scanView(spec, scan.ranges));
#ifdef ROOMBA_RRT_WITH_MRPT
      mrpt_map.insertObservation(mrptScan(spec, scan.ranges), mrptPose(at));
#endif
    }
    mapper.addBump(poses[0], robot.radius, bumper);
    simulator.move(tree.tick(bumper, poses[0]));
  }
  row.seconds = steps * world.step;
  const sim::CoverageGrid& grid = simulator.coverageGrid();
  row.coverage = std::min(1.0, static_cast<double>(grid.sweptFreeCells()) * grid.cellSize() *
                                   grid.cellSize() / cleaning.reachable_area);
  row.scans = mapper.scans();
  row.accuracy = mapping::compare(mapper.grid(), world);
#ifdef ROOMBA_RRT_WITH_MRPT
  row.with_mrpt = true;
  row.mrpt = mapping::compare(trinary(mrpt_map), world);
#endif
  return row;
}

struct Scans {
  std::vector<robot::Pose2D> poses;
  std::vector<std::vector<float>> ranges;
  sensors::RangeSensorSpec lds = sensors::ldsPreset();
  mapping::MapperOptions options;
};

/// 1024 LDS scans from random free poses of willow_full, inside a 1000 × 1000-cell region.
Scans willowScans(const world::World& world) {
  Scans s;
  const world::Room& room = world.room;
  const double cx = room.origin.x + room.width / 2, cy = room.origin.y + room.height / 2;
  s.options.xmin = cx - 25;
  s.options.xmax = cx + 25;
  s.options.ymin = cy - 25;
  s.options.ymax = cy + 25;
  const double margin = s.lds.range_max + 0.1;  // every ray inside: the grid does not grow
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(s.options.xmin + margin, s.options.xmax - margin);
  std::uniform_real_distribution<double> y(s.options.ymin + margin, s.options.ymax - margin);
  std::uniform_real_distribution<double> theta(-M_PI, M_PI);
  const sensors::RayCaster caster(room);
  const sensors::RayFan fan(s.lds);
  std::mt19937 noise;
  while (s.poses.size() < 1024) {
    const robot::Pose2D p{x(rng), y(rng), theta(rng)};
    if (world::penetrates(world, 0.17, p.x, p.y)) continue;
    s.poses.push_back(p);
    s.ranges.emplace_back();
    sensors::measure(caster, s.lds, fan, p, {}, noise, s.ranges.back());
  }
  return s;
}

/// Cells per scan: those an exact walk visits (every cell a ray crosses: |Δi| + |Δj| + 1) and
/// those a Bresenham line (MRPT's) visits (max(|Δi|, |Δj|) + 1).
std::pair<double, double> cellsPerScan(const Scans& s) {
  double exact = 0, line = 0;
  const double r = s.options.resolution;
  for (std::size_t k = 0; k < s.poses.size(); ++k) {
    for (int ray = 0; ray < s.lds.samples; ++ray) {
      const float range = s.ranges[k][static_cast<std::size_t>(ray)];
      const double length = std::isfinite(range) ? range : s.lds.range_max;
      const double a = s.poses[k].theta + s.lds.angle_min + ray * s.lds.angleIncrement();
      const double x0 = s.poses[k].x / r, y0 = s.poses[k].y / r;
      const double di = std::abs(std::floor(x0 + length * std::cos(a) / r) - std::floor(x0));
      const double dj = std::abs(std::floor(y0 + length * std::sin(a) / r) - std::floor(y0));
      exact += di + dj + 1;
      line += std::max(di, dj) + 1;
    }
  }
  const double n = static_cast<double>(s.poses.size());
  return {exact / n, line / n};
}

/// CPU µs per scan added to our grid.
double oursMicroseconds(const Scans& s, long count) {
  mapping::OccupancyMapper mapper(s.options);
  for (std::size_t k = 0; k < s.poses.size(); ++k) {  // warm-up: the pages are touched
    mapper.addScan(s.poses[k], mapping::scanView(s.lds, s.ranges[k]));
  }
  const double start = threadCpuSeconds();
  for (long k = 0; k < count; ++k) {
    const std::size_t i = static_cast<std::size_t>(k) & 1023;
    mapper.addScan(s.poses[i], mapping::scanView(s.lds, s.ranges[i]));
  }
  return 1e6 * (threadCpuSeconds() - start) / static_cast<double>(count);
}

#ifdef ROOMBA_RRT_WITH_MRPT
/// CPU µs per scan inserted into MRPT's COccupancyGridMap2D (the same grid, rays and poses;
/// no return = free up to range_max, as REP 117 and ours).
double mrptMicroseconds(const Scans& s, long count) {
  mrpt::maps::COccupancyGridMap2D map = mrptGrid(s.options, s.lds.range_max);
  std::vector<mrpt::obs::CObservation2DRangeScan> observations;
  for (const std::vector<float>& ranges : s.ranges) observations.push_back(mrptScan(s.lds, ranges));
  for (std::size_t k = 0; k < s.poses.size(); ++k) {
    map.insertObservation(observations[k], mrptPose(s.poses[k]));
  }
  const double start = threadCpuSeconds();
  for (long k = 0; k < count; ++k) {
    const std::size_t i = static_cast<std::size_t>(k) & 1023;
    map.insertObservation(observations[i], mrptPose(s.poses[i]));
  }
  return 1e6 * (threadCpuSeconds() - start) / static_cast<double>(count);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  bool json = false;
  long scans = 4000;
  std::string maps = ROOMBA_RRT_SHARED_MAPS;
  bench::Arguments args(argc, argv, "mapping_bench", kUsage);
  while (args.next()) {
    if (args.is("--json")) {
      json = true;
    } else if (args.is("--scans")) {
      scans = args.count(1);
    } else if (args.is("--maps")) {
      maps = args.value();
    } else {
      args.unknown();
    }
  }
  const std::string willow = maps + "/willow_full.yaml";
  if (!std::filesystem::exists(willow)) {
    std::fprintf(stderr, "mapping_bench: needs %s\n", willow.c_str());
    return 1;
  }
  std::vector<AccuracyRow> rows;
  rows.push_back(
      cleaningRun("furnished room",
                  tools::loadToolWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml", "")));
  rows.push_back(cleaningRun("willow_full --crop -16,-4,-8,3.5",
                             tools::loadToolWorld(willow, "-12,0", "-16,-4,-8,3.5")));
  const Scans s = willowScans(world::readWorldFile(willow).world);
  const double ours = oursMicroseconds(s, scans);
  double mrpt = -1;
#ifdef ROOMBA_RRT_WITH_MRPT
  mrpt = mrptMicroseconds(s, scans);
#endif
  const auto [exact_cells, line_cells] = cellsPerScan(s);
  const long cells = std::lround((s.options.xmax - s.options.xmin) / s.options.resolution) *
                     std::lround((s.options.ymax - s.options.ymin) / s.options.resolution);
  if (json) {
    std::printf("{\"accuracy\": [");
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const AccuracyRow& r = rows[k];
      std::printf(
          "%s{\"world\": \"%s\", \"agreement\": %.6f, \"known\": %zu, \"occupied\": %zu, "
          "\"walls_off\": %zu, \"seconds\": %.1f, \"coverage\": %.4f, \"bumps\": %d, "
          "\"scans\": %zu",
          k ? ", " : "", r.world.c_str(), r.accuracy.agreement(), r.accuracy.known,
          r.accuracy.occupied, r.accuracy.walls_off, r.seconds, r.coverage, r.bumps, r.scans);
      if (r.with_mrpt) {
        std::printf(", \"mrpt\": {\"agreement\": %.6f, \"known\": %zu, \"walls_off\": %zu}",
                    r.mrpt.agreement(), r.mrpt.known, r.mrpt.walls_off);
      }
      std::printf("}");
    }
    std::printf(
        "], \"update\": {\"cells\": %ld, \"rays\": %d, \"scans\": %ld, \"ours_us\": %.3f, "
        "\"cells_per_scan\": %.0f, \"line_cells_per_scan\": %.0f",
        cells, s.lds.samples, scans, ours, exact_cells, line_cells);
    if (mrpt >= 0) std::printf(", \"mrpt_us\": %.3f", mrpt);
    std::printf("}}\n");
    return 0;
  }
  for (const AccuracyRow& r : rows) {
    std::printf(
        "%-34s %6.2f %% of %zu seen cells agree, %zu occupied, %zu off by more than a "
        "cell; %.0f s, %.1f %% cleaned, %d bumps, %zu scans\n",
        r.world.c_str(), 100 * r.accuracy.agreement(), r.accuracy.known, r.accuracy.occupied,
        r.accuracy.walls_off, r.seconds, 100 * r.coverage, r.bumps, r.scans);
    if (r.with_mrpt) {
      std::printf(
          "%-34s %6.2f %% of %zu seen cells agree in MRPT's grid fed the same scans, %zu "
          "occupied cells off by more than a cell\n",
          "", 100 * r.mrpt.agreement(), r.mrpt.known, r.mrpt.walls_off);
    }
  }
  std::printf("one %d-ray scan on %ld cells: ours %.1f µs (%.0f cells crossed)", s.lds.samples,
              cells, ours, exact_cells);
  if (mrpt >= 0) {
    std::printf(", MRPT COccupancyGridMap2D %.1f µs (a line of %.0f cells)", mrpt, line_cells);
  }
  std::printf("\n");
  return 0;
}
