// Loading and inflating a large map (issue 17, item 6): a shared map upsampled k× (each cell
// becomes k × k cells, resolution / k), written as PGM + YAML to a temporary folder, then
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
//   map_load_bench [--map FILE.yaml] [--factor 8] [--reps 3] [--json]
//
// Default: ../shared/maps/willow_full.yaml × 8 = 4320 × 4696 cells (20.3 M).
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
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
#include <vector>

#include "arguments.h"
#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/geometry/map_file.h"

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

/// Writes `map` upsampled `factor`× into `folder` (map.pgm, map.yaml); returns the YAML's path.
std::string writeUpsampled(const geometry::MapFile& map, int factor, const fs::path& folder) {
  const Pgm pgm = readPgm(map.image);
  const std::size_t w = static_cast<std::size_t>(pgm.width) * factor;
  {
    std::ofstream out(folder / "map.pgm", std::ios::binary);
    out << "P5\n" << w << " " << pgm.height * factor << "\n255\n";
    std::vector<char> row(w);
    for (int j = 0; j < pgm.height; ++j) {
      for (std::size_t i = 0; i < w; ++i) row[i] = pgm.pixels[j * pgm.width + i / factor];
      for (int k = 0; k < factor; ++k) out.write(row.data(), static_cast<std::streamsize>(w));
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
  int reps = 3;
  bool json = false;
};

Config parseArgs(int argc, char** argv) {
  Config cfg;
  roomba_rrt::bench::Arguments args(
      argc, argv, "map_load_bench",
      "usage: map_load_bench [--map FILE.yaml] [--factor K] [--reps N] [--json]\n");
  while (args.next()) {
    if (args.is("--json")) {
      cfg.json = true;
    } else if (args.is("--map")) {
      cfg.map = args.value();
    } else if (args.is("--factor")) {
      cfg.factor = args.count(1);
    } else if (args.is("--reps")) {
      cfg.reps = args.count(1);
    } else {
      args.unknown();
    }
  }
  return cfg;
}

int run(const Config& cfg, const fs::path& folder) {
  const std::string yaml = writeUpsampled(geometry::loadMap(cfg.map), cfg.factor, folder);
  const double rss_before = peakRssBytes();  // the small original and the writer's buffers
  std::vector<double> load_s, inflate_s;
  int width = 0, height = 0;
  double peak = 0;
  std::uint64_t checksum = 1469598103934665603u;  // FNV-1a of every cell's distance (untimed)
  for (int rep = 0; rep < cfg.reps; ++rep) {
    double t0 = threadCpuSeconds();
    auto grid = std::make_shared<const geometry::OccupancyGrid>(geometry::loadMap(yaml).grid);
    load_s.push_back(threadCpuSeconds() - t0);
    t0 = threadCpuSeconds();
    const geometry::ClearanceMap map(grid);
    inflate_s.push_back(threadCpuSeconds() - t0);
    width = grid->width, height = grid->height;
    if (rep == 0) {
      peak = peakRssBytes();  // one map, loaded and inflated: what a planner holds at most
      for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
          checksum = (checksum ^ static_cast<std::uint32_t>(map.squaredCellDistance(i, j))) *
                     1099511628211u;
        }
      }
    }
  }
  const double cells = static_cast<double>(width) * height;
  const double load_ns = median(load_s) * 1e9 / cells, inflate_ns = median(inflate_s) * 1e9 / cells;
  const double kept = 1 + geometry::ClearanceMap::kBytesPerCell;
  const double peak_per_cell = (peak - rss_before) / cells;
  if (cfg.json) {
    std::cout << "{\"map\": \"" << fs::path(cfg.map).stem().string()
              << "\", \"factor\": " << cfg.factor << ", \"width\": " << width
              << ", \"height\": " << height << ", \"reps\": " << cfg.reps
              << ", \"load_ns_per_cell\": " << load_ns
              << ", \"inflate_ns_per_cell\": " << inflate_ns
              << ", \"total_ns_per_cell\": " << load_ns + inflate_ns
              << ", \"total_ms\": " << (load_ns + inflate_ns) * cells * 1e-6
              << ", \"kept_bytes_per_cell\": " << kept << ", \"peak_rss_mb\": " << peak / (1 << 20)
              << ", \"peak_bytes_per_cell\": " << peak_per_cell << ", \"distance_checksum\": \""
              << std::hex << checksum << std::dec << "\"}\n";
  } else {
    std::cout << fs::path(cfg.map).stem().string() << " x" << cfg.factor << ": " << width << " x "
              << height << " cells; load " << load_ns << " ns/cell, inflate " << inflate_ns
              << " ns/cell, total " << load_ns + inflate_ns << " ns/cell ("
              << (load_ns + inflate_ns) * cells * 1e-6 << " ms); kept " << kept
              << " B/cell; peak RSS " << peak / (1 << 20) << " MB (" << peak_per_cell
              << " B/cell above the start); distance checksum " << std::hex << checksum << std::dec
              << "\n";
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
