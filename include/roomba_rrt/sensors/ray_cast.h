// Casting a sensor's rays into the room: the exact distance along a ray to the first wall, piece
// of furniture or blocked map cell, the same closed shapes contact pushes the robot out of (the
// room's rectangle, circles, axis-aligned rectangles, each blocked cell's square). ROS-free.
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/sensors/blocked_bits.h"
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

/// Casts rays into one room. Built once per room (the map's blocked cells become bits here: a
/// quarter of a byte per cell, along the rows and along the columns); cheap to query from many
/// threads at once (const).
class RayCaster {
 public:
  explicit RayCaster(const world::Room& room);

  /// The distance (m) from ray.origin to the first wall, piece of furniture, blocked map cell
  /// or disc of `others` (other robots) along the ray, if it is at most `max_range`; +inf
  /// beyond. A map is walked line by line across the ray's main direction: the cells the ray
  /// touches in one row (one column for a ray closer to the y axis) are a run that one word of
  /// BlockedBits tests, and only a blocked square among them is intersected.
  double cast(const Ray& ray, double max_range,
              const std::vector<geometry::Circle>& others = {}) const;

  const world::Room& room() const { return room_; }

 private:
  double castMap(const Ray& ray, double max_range) const;
  // The map walk, in cells (ray_cast.cpp): u is the ray's main axis (x when kAlongX), v the other;
  // (pu, pv) the origin, (du, dv) the direction, kSu and kSv their signs; a..b cells of line v.
  template <bool kAlongX>
  double walk(const Ray& ray, double pu, double pv, double du, double dv, double limit) const;
  template <bool kAlongX, int kSu>
  double walkAlongLine(const Ray& ray, double pu, double pv, double limit) const;
  template <bool kAlongX, int kSu, int kSv>
  double walkAcrossLines(const Ray& ray, double pu, double pv, double du, double dv,
                         double limit) const;
  template <bool kAlongX, int kSu>
  double firstInRun(const Ray& ray, int v, int a, int b) const;
  template <bool kAlongX, int kSu>
  double firstOfBits(const Ray& ray, int v, int u0, std::uint64_t blocked) const;
  template <bool kAlongX>
  double hitCell(const Ray& ray, int u, int v) const;

  world::Room room_;
  geometry::Rectangle walls_;  ///< the room's rectangle
  /// The map's blocked cells along its rows (for rays closer to the x axis) and along its
  /// columns (the others).
  BlockedBits rows_, columns_;
  double inv_resolution_ = 0;
};

}  // namespace roomba_rrt::sensors
