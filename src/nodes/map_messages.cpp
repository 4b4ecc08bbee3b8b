#include "map_messages.h"

#include <cmath>
#include <sstream>

#include "message_parts.h"

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

std::string fromMapMessage(const nav_msgs::OccupancyGrid& message, geometry::OccupancyGrid* grid) {
  const nav_msgs::MapMetaData& info = message.info;
  std::ostringstream why;
  const double resolution = info.resolution;
  const double x = info.origin.position.x, y = info.origin.position.y;
  const auto& q = info.origin.orientation;
  const long long cells = static_cast<long long>(info.width) * info.height;
  if (!(std::isfinite(resolution) && resolution > 0)) {
    why << "info.resolution: must be a finite number > 0, got " << resolution;
  } else if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e6 || std::abs(y) > 1e6) {
    why << "info.origin.position: must be finite and within 1e6 m, got (" << x << ", " << y << ")";
  } else if (info.width == 0 || info.height == 0 || cells > kMaxMapMessageCells) {
    why << "info.width, info.height: " << info.width << " x " << info.height
        << " cells; must be 1 to " << kMaxMapMessageCells << " cells";
  } else if (message.data.size() != static_cast<std::size_t>(cells)) {
    why << "data: " << message.data.size() << " cells for " << info.width << " x " << info.height;
  } else {
    // A yaw other than 0 (a rotated map) is refused; an unset quaternion (all 0) reads as none.
    const double yaw = quaternionToYaw(q);
    if (!(std::abs(yaw) < 1e-6) || !std::isfinite(q.w)) {
      why << "info.origin.orientation: a rotated map (yaw " << yaw << " rad) is not supported";
    }
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
