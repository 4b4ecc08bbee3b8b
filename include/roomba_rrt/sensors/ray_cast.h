// Casting a sensor's rays into the room: the exact distance along a ray to the first wall, piece
// of furniture or blocked map cell, the same closed shapes contact pushes the robot out of (the
// room's rectangle, circles, axis-aligned rectangles, each blocked cell's square). ROS-free.
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sensors {

/// A ray from `origin` along the unit vector (dx, dy).
struct Ray {
  geometry::Point2 origin;
  double dx = 1;
  double dy = 0;
};

/// The ray's first contact with each kind of shape: the least t ≥ 0 at which origin + t·(dx, dy)
/// lies in the closed shape (0 when the origin is in it; touching counts), or +inf when it never
/// does. Exact up to floating-point rounding of one formula; also the test oracle's pieces.
double hitCircle(const Ray& ray, const geometry::Circle& circle);
double hitRectangle(const Ray& ray, const geometry::Rectangle& box);
/// Where the ray leaves the room's rectangle (the walls are everything outside it): 0 when the
/// origin is on or outside its border.
double leaveRectangle(const Ray& ray, const geometry::Rectangle& room);

/// Casts rays into one room. Built once per room (the map's clearance is computed here: one
/// byte per cell); cheap to query from many threads at once (const).
class RayCaster {
 public:
  explicit RayCaster(const world::Room& room);

  /// The distance (m) from ray.origin to the first wall, piece of furniture, blocked map cell
  /// or disc of `others` (other robots) along the ray, if it is at most `max_range`; +inf
  /// beyond. A map is walked cell by cell (a DDA), jumping over runs of free cells known from
  /// each cell's clearance.
  double cast(const Ray& ray, double max_range,
              const std::vector<geometry::Circle>& others = {}) const;

  const world::Room& room() const { return room_; }

 private:
  double castMap(const Ray& ray, double max_range) const;

  world::Room room_;
  geometry::Rectangle walls_;  ///< the room's rectangle
  /// Per map cell: the Chebyshev distance (in cells, at most 255) to the nearest blocked cell,
  /// 0 on a blocked one: the cells within clearance − 1 of it in both axes are all free.
  std::vector<std::uint8_t> clearance_;
};

}  // namespace roomba_rrt::sensors
