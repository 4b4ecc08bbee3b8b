#include "roomba_rrt/mapping/map_saver.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::mapping {
namespace {

void write(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  out.close();
  if (!out) throw util::InvalidInput(path, "cannot be written");
}

/// `v` as the shortest text that reads back as it, or, when `v` is a float (a resolution from
/// nav_msgs/MapMetaData, whose field is float32), as the same float: 0.05, not
/// 0.05000000074505806.
std::string number(double v) {
  const bool is_float = static_cast<double>(static_cast<float>(v)) == v;
  const auto same = [&](const std::string& text) {
    const double back = std::strtod(text.c_str(), nullptr);
    return back == v || (is_float && static_cast<float>(back) == static_cast<float>(v));
  };
  std::string text = util::show(v);  // 6 digits, as a person writes it ("-10", "0.05")
  for (int digits = 7; digits <= 17 && !same(text); ++digits) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    text = buffer;
  }
  return text;
}

}  // namespace

std::uint8_t pgmValue(std::int8_t v, const SaveThresholds& thresholds) {
  if (v >= 0 && v <= thresholds.free) return 254;
  if (v >= thresholds.occupied) return 0;
  return 205;
}

std::string pgmImage(const geometry::OccupancyGrid& grid, const SaveThresholds& thresholds) {
  char header[128];
  std::snprintf(header, sizeof header, "P5\n# CREATOR: roomba_map_saver %.3f m/pix\n%d %d\n255\n",
                grid.resolution, grid.width, grid.height);
  std::string image(header);
  const std::size_t start = image.size();
  image.resize(start + static_cast<std::size_t>(grid.width) * grid.height);
  std::size_t k = start;
  for (int j = grid.height - 1; j >= 0; --j) {  // the image's first row is the grid's top
    for (int i = 0; i < grid.width; ++i) {
      image[k++] = static_cast<char>(pgmValue(grid.at(i, j), thresholds));
    }
  }
  return image;
}

std::string mapYaml(const geometry::OccupancyGrid& grid, const std::string& image) {
  std::ostringstream yaml;
  yaml << "image: " << image << "\nresolution: " << number(grid.resolution) << "\norigin: ["
       << number(grid.origin.x) << ", " << number(grid.origin.y)
       << ", 0]\nnegate: 0\noccupied_thresh: 0.65\n"
       << "free_thresh: 0.196\n";
  return yaml.str();
}

std::string saveMap(const geometry::OccupancyGrid& grid, const std::string& name,
                    const SaveThresholds& thresholds) {
  if (grid.width <= 0 || grid.height <= 0 ||
      grid.cells.size() != static_cast<std::size_t>(grid.width) * grid.height) {
    throw util::InvalidInput("map", "has no cells");
  }
  const std::string pgm = name + ".pgm", yaml = name + ".yaml";
  write(pgm, pgmImage(grid, thresholds));
  write(yaml, mapYaml(grid, std::filesystem::path(pgm).filename().string()));
  return yaml;
}

}  // namespace roomba_rrt::mapping
