// Maps as map_server reads them: a YAML file naming an image (PGM or PNG) and how to read it.
//
//   image: apartment.pgm        # relative to the YAML file (or absolute)
//   resolution: 0.05            # m per cell
//   origin: [-10.0, -10.0, 0.0] # the lower-left cell's corner: x, y (m) and yaw (0 only)
//   negate: 0                   # 1: white is occupied
//   occupied_thresh: 0.65       # occupancy above this: occupied (100)
//   free_thresh: 0.196          # occupancy below this: free (0); between the two: unknown (-1)
//   mode: trinary               # optional; trinary is the only mode read
//
// Each pixel becomes the cell of the same column, the image's top row the grid's top row (the
// grid's row 0 is the image's last). Its occupancy is map_server's: the average of the pixel's
// bytes p (every channel, alpha included, as map_server averages in trinary mode; one byte for
// grey), occ = (255 − p) / 255, or p / 255 with negate. The image is decoded to the bytes
// SDL2_image, map_server's decoder, gives map_server (map_image.h: netpbm read here, PNG through
// libpng), so that every PGM (P2, P5) and PNG map_server reads gives the same cells here.
#pragma once

#include <cstddef>
#include <string>

#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::geometry {

/// What is read, and how much of it at most.
struct MapLimits {
  static constexpr std::size_t kMaxYamlBytes = 1 << 20;                ///< a map YAML ≤ 1 MiB
  static constexpr std::size_t kMaxImageBytes = std::size_t{1} << 30;  ///< an image ≤ 1 GiB
  static constexpr long long kMaxCells = 100'000'000;  ///< 100 M cells (100 MB of grid)
  static constexpr double kMinResolution = 1e-4;       ///< m
  static constexpr double kMaxResolution = 100;        ///< m
  static constexpr double kMaxCoordinate = 1e6;        ///< |origin| ≤ this, m
};

/// How a map's source spells the fields validateMapPlacement() names: a map file's keys by
/// default; a nav_msgs/OccupancyGrid's "info.resolution", "info.origin.position.x", ...
struct MapFieldNames {
  std::string resolution = "resolution";
  std::string x = "origin[0]";
  std::string y = "origin[1]";
  std::string rotation = "origin[2]";
};

/// The one check of where a map lies, whichever way it comes (a map_server file, or a message on
/// /map), as strict as map_server: a resolution in [kMinResolution, kMaxResolution] m, an origin
/// within kMaxCoordinate m, and no rotation (`rotation`, rad: the yaw of a file's origin, the
/// angle of a message's quaternion; a rotated map is refused, not read as an unrotated one).
/// Throws util::InvalidInput naming the field as `names` spells it.
void validateMapPlacement(double resolution, double x, double y, double rotation,
                          const MapFieldNames& names = {});

/// A map_server YAML and the grid it describes.
struct MapFile {
  std::string yaml;   ///< the YAML file as given
  std::string image;  ///< the image's path (resolved against the YAML's folder)
  double resolution = 0;
  Point2 origin;
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  OccupancyGrid grid;
};

/// Reads a map_server YAML and its image. Throws util::InvalidInput naming the file and the
/// field: a YAML that is not a small readable file or not a mapping, an unknown or repeated key,
/// an anchor or alias, a key map_server requires missing (`image`, `resolution`, `origin`,
/// `negate`, `occupied_thresh`, `free_thresh`; `mode` is optional), a non-numeric value, a
/// placement validateMapPlacement() refuses, `negate` other than 0 or 1, thresholds outside
/// [0, 1] or free_thresh ≥ occupied_thresh, a `mode` other than trinary; an image that is missing,
/// unreadable, truncated, not PGM or PNG, or has more than `max_cells` pixels (checked from its
/// header, before any pixel is decoded).
MapFile loadMap(const std::string& yaml_path, long long max_cells = MapLimits::kMaxCells);

/// Whether `path` looks like a map_server YAML (it has an `image:` key at the top level): what
/// the simulator asks of a world file given to it.
bool isMapYaml(const std::string& path);

/// map_server's trinary reading of one pixel whose bytes average to `average` (0..255).
std::int8_t trinaryValue(double average, bool negate, double occupied_thresh, double free_thresh);

}  // namespace roomba_rrt::geometry
