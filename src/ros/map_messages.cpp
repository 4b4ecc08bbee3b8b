#include "map_messages.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "message_parts.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::nodes {

nav_msgs::OccupancyGrid toMapMessage(const geometry::OccupancyGrid& grid, const ros::Time& stamp) {
  nav_msgs::OccupancyGrid map;
  map.header.stamp = stamp;
  map.header.frame_id = "map";
  map.info = toMapMetaData(grid, stamp);
  map.data.assign(grid.cells.begin(), grid.cells.end());
  return map;
}

nav_msgs::MapMetaData toMapMetaData(const geometry::OccupancyGrid& grid, const ros::Time& stamp) {
  nav_msgs::MapMetaData info;
  info.map_load_time = stamp;
  info.resolution = static_cast<float>(grid.resolution);
  info.width = grid.width;
  info.height = grid.height;
  info.origin.position.x = grid.origin.x;
  info.origin.position.y = grid.origin.y;
  info.origin.orientation.w = 1.0;
  return info;
}

namespace {

/// The angle (rad) a quaternion turns by about any axis, roll and pitch included: 0 for the
/// identity and for an unset quaternion (all 0), NaN when a component is not finite.
double rotationAngle(const geometry_msgs::Quaternion& q) {
  for (const double c : {q.x, q.y, q.z, q.w}) {
    if (!std::isfinite(c)) return NAN;
  }
  const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), std::abs(q.w)});
  if (largest == 0) return 0;
  const double x = q.x / largest, y = q.y / largest, z = q.z / largest, w = q.w / largest;
  return 2 * std::atan2(std::sqrt(x * x + y * y + z * z), std::abs(w));
}

}  // namespace

std::string fromMapMessage(const nav_msgs::OccupancyGrid& message, geometry::OccupancyGrid* grid) {
  const nav_msgs::MapMetaData& info = message.info;
  std::ostringstream why;
  const double resolution = info.resolution;
  const double x = info.origin.position.x, y = info.origin.position.y;
  // Two uint32 multiply to at most 2^64 - 2^33 + 1: unsigned, so 4e9 x 4e9 does not overflow.
  const unsigned long long cells = static_cast<unsigned long long>(info.width) * info.height;
  try {
    // The checks a map file gets (map_file.h), spelled as the message's fields.
    static const geometry::MapFieldNames kNames{"info.resolution", "info.origin.position.x",
                                                "info.origin.position.y",
                                                "info.origin.orientation"};
    geometry::validateMapPlacement(resolution, x, y, rotationAngle(info.origin.orientation),
                                   kNames);
  } catch (const util::InvalidInput& e) {
    return e.what();
  }
  if (info.width == 0 || info.height == 0 ||
      cells > static_cast<unsigned long long>(kMaxMapMessageCells)) {
    why << "info.width, info.height: " << info.width << " x " << info.height
        << " cells; must be 1 to " << kMaxMapMessageCells << " cells";
  } else if (message.data.size() != static_cast<std::size_t>(cells)) {
    why << "data: " << message.data.size() << " cells for " << info.width << " x " << info.height;
  }
  if (!why.str().empty()) return why.str();
  grid->width = static_cast<int>(info.width);
  grid->height = static_cast<int>(info.height);
  grid->resolution = resolution;
  grid->origin = {x, y};
  grid->cells.assign(message.data.begin(), message.data.end());
  return "";
}

}  // namespace roomba_rrt::nodes
