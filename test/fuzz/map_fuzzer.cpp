// libFuzzer harness: a map_server map, YAML and image, → loadMap → (if accepted) the grid's
// invariants and the disc queries over it. The input is the YAML text, a line "---IMAGE---" and
// the image's bytes (PGM or PNG, decoded by SDL2_image); without that line, all of it is the
// image beside a fixed YAML. Anything but a clean util::InvalidInput, or a grid that does not
// match what was read, is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/util/invalid_input.h"

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "map_fuzzer: check failed: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  using namespace roomba_rrt::geometry;
  static const fs::path dir =
      fs::temp_directory_path() / ("map_fuzzer_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n---IMAGE---\n";
  const std::size_t at = input.find(separator);
  const std::string yaml =
      at == std::string::npos
          ? "image: map.img\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
          : input.substr(0, at);
  const std::string image = at == std::string::npos ? input : input.substr(at + separator.size());
  std::ofstream(dir / "map.yaml", std::ios::binary | std::ios::trunc) << yaml;
  std::ofstream(dir / "map.img", std::ios::binary | std::ios::trunc) << image;
  MapFile map;
  try {
    map = loadMap((dir / "map.yaml").string(), /*max_cells=*/1 << 20);  // small: fast runs
  } catch (const roomba_rrt::util::InvalidInput&) {
    return 0;  // refused with a message naming the file and the field: fine
  }
  const OccupancyGrid& grid = map.grid;
  check(grid.width > 0 && grid.height > 0, "a grid with cells");
  check(grid.cells.size() == static_cast<std::size_t>(grid.width) * grid.height, "cells = w * h");
  for (const std::int8_t c : grid.cells) {
    check(
        c == OccupancyGrid::kFree || c == OccupancyGrid::kOccupied || c == OccupancyGrid::kUnknown,
        "trinary values");
  }
  check(grid.resolution == map.resolution && grid.resolution > 0, "the resolution read");
  const Rectangle extent = grid.extent();
  const Point2 centre{0.5 * (extent.min_x + extent.max_x), 0.5 * (extent.min_y + extent.max_y)};
  const double d = distanceToBlocked(grid, centre, 10 * grid.resolution);
  check(d >= 0 && d <= 10 * grid.resolution, "a distance within reach");
  // The disc of radius d meets a blocked square (up to the rounding of d's square root).
  check(discMeetsBlocked(grid, centre, d * (1 + 1e-12) + 1e-12) || d == 10 * grid.resolution,
        "the disc meets at d");
  return 0;
}
