// Loading, inflating and planning across a large map (issues 17 and 47): a shared map upsampled
// k× (`--factor`: each cell becomes k × k cells, resolution / k) or tiled t × t (`--tile`: t
// copies side by side and t rows of them, resolution kept), written as PGM + YAML to a
// temporary folder, then
//   load     geometry::loadMap(): the YAML, the PGM decoded by SDL2_image, map_server's trinary
//            reading of every pixel into the grid;
//   inflate  geometry::ClearanceMap's constructor: the exact distance transform of the blocked
//            cells and the marking of cells inside walls;
// each timed in CPU time of this thread (median of --reps), in ns per cell, and the memory per
// cell: what the planner keeps (the grid's byte + ClearanceMap::kBytesPerCell) and the process's
// peak resident set (getrusage) after the first load and inflation, above what it held before.
//
// The FNV-1a checksum of every cell's distance value is printed too (not timed): an optimised
// transform must give the same number.
//
// `--plans N`: then N RRT-Connect solves across the whole map (a start in the first tile or
// corner, a goal in the last, at least half the map's diagonal apart; radius 0.17 m, range 20
// cells, one seed each), each timed in CPU time: solved, p50 and p95, mean path length. The
// peak RSS then includes the planner's tree.
//
//   map_load_bench [--map FILE.yaml] [--factor 8 | --tile T] [--reps 3] [--plans N] [--json]
//
// Default: ../shared/maps/willow_full.yaml × 8 = 4320 × 4696 cells (20.3 M). The 10^8-cell map
// of scripts/bench: --map nav2_bench_100by100_15.yaml --tile 5 (10 000 × 10 000 cells; that
// map's border is free floor, so the tiles join into one floor).
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "arguments.h"
#include "far_apart_pairs.h"
#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/planning/planner.h"

namespace {

namespace fs = std::filesystem;
namespace geometry = roomba_rrt::geometry;

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double peakRssBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss * 1024.0;  // Linux reports KiB
}

/// The pixels of an 8-bit binary PGM (P5, maxval ≤ 255): the shared maps' format.
struct Pgm {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
};

Pgm readPgm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  in >> magic;
  auto skipComments = [&in] {
    in >> std::ws;
    while (in.peek() == '#') {
      in.ignore(1 << 20, '\n');
      in >> std::ws;
    }
  };
  Pgm pgm;
  int maxval = 0;
  skipComments();
  in >> pgm.width;
  skipComments();
  in >> pgm.height;
  skipComments();
  in >> maxval;
  in.get();  // the one whitespace before the pixels
  if (magic != "P5" || !in || pgm.width < 1 || pgm.height < 1 || maxval > 255) {
    throw std::runtime_error(path + ": not an 8-bit binary PGM (P5)");
  }
  pgm.pixels.resize(static_cast<std::size_t>(pgm.width) * pgm.height);
  in.read(reinterpret_cast<char*>(pgm.pixels.data()),
          static_cast<std::streamsize>(pgm.pixels.size()));
  if (!in) throw std::runtime_error(path + ": truncated");
  return pgm;
}

/// Writes `map` upsampled `factor`× and tiled `tiles` × `tiles` into `folder` (map.pgm,
/// map.yaml); returns the YAML's path.
std::string writeScaled(const geometry::MapFile& map, int factor, int tiles,
                        const fs::path& folder) {
  const Pgm pgm = readPgm(map.image);
  const std::size_t tile_w = static_cast<std::size_t>(pgm.width) * factor;
  const std::size_t w = tile_w * tiles;
  {
    std::ofstream out(folder / "map.pgm", std::ios::binary);
    out << "P5\n" << w << " " << static_cast<std::size_t>(pgm.height) * factor * tiles << "\n255\n";
    std::vector<char> row(w);
    for (int copy = 0; copy < tiles; ++copy) {
      for (int j = 0; j < pgm.height; ++j) {
        for (std::size_t i = 0; i < w; ++i) {
          row[i] = static_cast<char>(pgm.pixels[j * pgm.width + (i % tile_w) / factor]);
        }
        for (int k = 0; k < factor; ++k) out.write(row.data(), static_cast<std::streamsize>(w));
      }
    }
    if (!out) throw std::runtime_error("cannot write " + (folder / "map.pgm").string());
  }
  const fs::path yaml = folder / "map.yaml";
  std::ofstream out(yaml);
  out.precision(17);
  out << "image: map.pgm\nresolution: " << map.resolution / factor << "\norigin: [" << map.origin.x
      << ", " << map.origin.y << ", 0.0]\nnegate: " << (map.negate ? 1 : 0)
      << "\noccupied_thresh: " << map.occupied_thresh << "\nfree_thresh: " << map.free_thresh
      << "\n";
  if (!out) throw std::runtime_error("cannot write " + yaml.string());
  return yaml.string();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Config {
  std::string map = ROOMBA_RRT_SHARED_MAPS "/willow_full.yaml";
  int factor = 8;
  int tiles = 1;
  int reps = 3;
  int plans = 0;
  bool json = false;
};

Config parseArgs(int argc, char** argv) {
  Config cfg;
  roomba_rrt::bench::Arguments args(argc, argv, "map_load_bench",
                                    "usage: map_load_bench [--map FILE.yaml] [--factor K | --tile "
                                    "T] [--reps N] [--plans N] [--json]\n");
  bool tiled = false;
  while (args.next()) {
    if (args.is("--json")) {
      cfg.json = true;
    } else if (args.is("--map")) {
      cfg.map = args.value();
    } else if (args.is("--factor")) {
      cfg.factor = args.count(1);
    } else if (args.is("--tile")) {
      cfg.tiles = args.count(1);
      tiled = true;
    } else if (args.is("--reps")) {
      cfg.reps = args.count(1);
    } else if (args.is("--plans")) {
      cfg.plans = args.count(0);
    } else {
      args.unknown();
    }
  }
  if (tiled) cfg.factor = 1;  // a tiled map keeps the map's resolution
  return cfg;
}

/// RRT-Connect across the map: `plans` solves between free points at least half the map's
/// diagonal apart.
struct PlanStats {
  int runs = 0, solved = 0;
  double p50_ms = 0, p95_ms = 0, max_ms = 0, mean_length = 0, mean_distance = 0;
};

namespace planning = roomba_rrt::planning;

PlanStats planAcross(const std::shared_ptr<const geometry::ClearanceMap>& map, int plans) {
  constexpr double kRadius = 0.17, kStepCells = 20;
  planning::Problem base;
  const geometry::Rectangle e = map->grid().extent();
  base.bounds = {e.min_x, e.max_x, e.min_y, e.max_y};
  base.map = map;
  base.robot_radius = kRadius;
  planning::PlannerOptions options;
  options.algorithm = planning::Algorithm::kRrtConnect;
  options.collision = planning::CollisionCheck::kSegments;
  options.step = kStepCells * map->grid().resolution;
  options.goal_bias = 0.05;
  options.max_iterations = 2000000;
  options.random_stream = planning::RandomStream::kFast;  // as the service plans on a map
  const auto pairs = roomba_rrt::bench::farApartPairs(*map, kRadius, plans);
  PlanStats stats;
  std::vector<double> ms;
  for (int i = 0; i < plans; ++i) {
    planning::Problem p = base;
    std::tie(p.start, p.goal) = pairs[i];
    options.seed = 42u + static_cast<std::uint32_t>(i);
    const double t0 = threadCpuSeconds();
    const planning::PlanResult result = planning::plan(p, options);
    ms.push_back((threadCpuSeconds() - t0) * 1e3);
    ++stats.runs;
    stats.mean_distance += geometry::distance(p.start, p.goal) / plans;
    if (result.success) {
      ++stats.solved;
      stats.mean_length += result.length;
    }
  }
  if (stats.solved > 0) stats.mean_length /= stats.solved;
  std::sort(ms.begin(), ms.end());
  if (!ms.empty()) {
    stats.p50_ms = ms[ms.size() / 2];
    stats.p95_ms = ms[std::min(ms.size() - 1, static_cast<std::size_t>(0.95 * ms.size()))];
    stats.max_ms = ms.back();
  }
  return stats;
}

int run(const Config& cfg, const fs::path& folder) {
  const std::string yaml = writeScaled(geometry::loadMap(cfg.map), cfg.factor, cfg.tiles, folder);
  const double rss_before = peakRssBytes();  // the small original and the writer's buffers
  std::vector<double> load_s, inflate_s;
  int width = 0, height = 0;
  double peak = 0;
  std::uint64_t checksum = 1469598103934665603u;  // FNV-1a of every cell's distance (untimed)
  std::shared_ptr<const geometry::ClearanceMap> kept_map;
  for (int rep = 0; rep < cfg.reps; ++rep) {
    kept_map.reset();  // one map at a time, as a planner holds it
    double t0 = threadCpuSeconds();
    auto grid = std::make_shared<const geometry::OccupancyGrid>(geometry::loadMap(yaml).grid);
    load_s.push_back(threadCpuSeconds() - t0);
    t0 = threadCpuSeconds();
    auto map = std::make_shared<const geometry::ClearanceMap>(grid);
    inflate_s.push_back(threadCpuSeconds() - t0);
    width = grid->width, height = grid->height;
    if (rep == 0) {
      peak = peakRssBytes();  // one map, loaded and inflated: what a planner holds at most
      for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
          checksum = (checksum ^ static_cast<std::uint32_t>(map->squaredCellDistance(i, j))) *
                     1099511628211u;
        }
      }
    }
    kept_map = std::move(map);
  }
  const PlanStats plans = planAcross(kept_map, cfg.plans);
  const double peak_planning = peakRssBytes();
  const double cells = static_cast<double>(width) * height;
  const double load_ns = median(load_s) * 1e9 / cells, inflate_ns = median(inflate_s) * 1e9 / cells;
  const double first_ns = (load_s[0] + inflate_s[0]) * 1e9 / cells;  // memory fresh from the OS
  const double kept = 1 + geometry::ClearanceMap::kBytesPerCell;
  const double peak_per_cell = (peak - rss_before) / cells;
  const std::string name = fs::path(cfg.map).stem().string();
  if (cfg.json) {
    std::cout << "{\"map\": \"" << name << "\", \"factor\": " << cfg.factor
              << ", \"tiles\": " << cfg.tiles << ", \"width\": " << width
              << ", \"height\": " << height << ", \"reps\": " << cfg.reps
              << ", \"load_ns_per_cell\": " << load_ns
              << ", \"inflate_ns_per_cell\": " << inflate_ns
              << ", \"total_ns_per_cell\": " << load_ns + inflate_ns
              << ", \"first_total_ns_per_cell\": " << first_ns
              << ", \"total_ms\": " << (load_ns + inflate_ns) * cells * 1e-6
              << ", \"kept_bytes_per_cell\": " << kept << ", \"peak_rss_mb\": " << peak / (1 << 20)
              << ", \"peak_bytes_per_cell\": " << peak_per_cell << ", \"distance_checksum\": \""
              << std::hex << checksum << std::dec << "\", \"plans\": {\"runs\": " << plans.runs
              << ", \"solved\": " << plans.solved << ", \"p50_ms\": " << plans.p50_ms
              << ", \"p95_ms\": " << plans.p95_ms << ", \"max_ms\": " << plans.max_ms
              << ", \"mean_length\": " << plans.mean_length
              << ", \"mean_distance\": " << plans.mean_distance
              << ", \"peak_rss_mb\": " << peak_planning / (1 << 20) << "}}\n";
  } else {
    std::cout << name << " x" << cfg.factor << " tiled " << cfg.tiles << "x" << cfg.tiles << ": "
              << width << " x " << height << " cells; load " << load_ns << " ns/cell, inflate "
              << inflate_ns << " ns/cell, total " << load_ns + inflate_ns << " ns/cell ("
              << (load_ns + inflate_ns) * cells * 1e-6 << " ms; the first of " << cfg.reps << " "
              << first_ns << " ns/cell); kept " << kept << " B/cell; peak RSS " << peak / (1 << 20)
              << " MB (" << peak_per_cell << " B/cell above the start); distance checksum "
              << std::hex << checksum << std::dec << "\n";
    if (plans.runs > 0) {
      std::cout << "RRT-Connect across the map: " << plans.solved << "/" << plans.runs
                << " solved, CPU p50 " << plans.p50_ms << " ms, p95 " << plans.p95_ms << " ms, max "
                << plans.max_ms << " ms; mean length " << plans.mean_length << " m (straight "
                << plans.mean_distance << " m); peak RSS " << peak_planning / (1 << 20) << " MB\n";
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Config cfg = parseArgs(argc, argv);
  const fs::path folder =
      fs::temp_directory_path() / ("map_load_bench." + std::to_string(static_cast<long>(getpid())));
  int status = 1;
  try {
    fs::create_directories(folder);
    status = run(cfg, folder);
  } catch (const std::exception& e) {
    std::cerr << "map_load_bench: " << e.what() << "\n";
  }
  std::error_code ignored;
  fs::remove_all(folder, ignored);
  return status;
}
