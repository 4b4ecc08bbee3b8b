// Saving a map as map_server's map_saver does, so that map_server (and geometry/map_file.h, and
// `roomba_sim --world NAME.yaml`) reads it back: NAME.pgm, one byte per cell, the grid's top row
// first, and NAME.yaml beside it:
//
//   image: NAME.pgm          # the image's file name, relative to the YAML
//   resolution: 0.05
//   origin: [-5, -5, 0]
//   negate: 0
//   occupied_thresh: 0.65
//   free_thresh: 0.196
//
// A cell ≥ 65 (occupied) is written 0 (black), a cell in [0, 25] (free) 254 (white), anything
// else (unknown, −1) 205 (grey): map_saver's thresholds, which map_server reads back as 100, 0
// and −1. ROS-free; roomba_map_saver is the tool.
#pragma once

#include <cstdint>
#include <string>

#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::mapping {

/// map_saver's thresholds on a cell's value (0..100).
struct SaveThresholds {
  int occupied = 65;  ///< ≥ this: occupied
  int free = 25;      ///< 0 to this: free
};

/// The PGM byte map_saver writes for a cell of value `v`.
std::uint8_t pgmValue(std::int8_t v, const SaveThresholds& thresholds = {});

/// The PGM image of `grid` (binary P5, with map_saver's comment line).
std::string pgmImage(const geometry::OccupancyGrid& grid, const SaveThresholds& thresholds = {});

/// The YAML naming `image` for `grid`. The numbers are written so that they read back exactly
/// (a resolution that is a float, as a message's, as the shortest text of that float).
std::string mapYaml(const geometry::OccupancyGrid& grid, const std::string& image);

/// Writes `name`.pgm and `name`.yaml (`name` may have a folder; the YAML names the image by its
/// file name). Returns the YAML's path. Throws util::InvalidInput naming the file that could not
/// be written, or "map" for a grid with no cells.
std::string saveMap(const geometry::OccupancyGrid& grid, const std::string& name,
                    const SaveThresholds& thresholds = {});

}  // namespace roomba_rrt::mapping
