// The planning world's plane geometry: the shared shapes of roomba_rrt/geometry (the simulator
// uses the same ones) and the box in which random points are drawn.
#pragma once

#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::planning {

using geometry::Circle;
using geometry::contains;
using geometry::distance;
using geometry::pathLength;
using geometry::Point2;
using geometry::Rectangle;
using geometry::Segment;
using geometry::segmentMeets;
using geometry::squaredDistance;

/// The axis-aligned box in which random points are drawn (the lab: [0, 10] x [0, 10]).
struct Bounds {
  double x_min = 0;
  double x_max = 10;
  double y_min = 0;
  double y_max = 10;
};

inline bool contains(const Bounds& bounds, const Point2& p) {
  return p.x >= bounds.x_min && p.x <= bounds.x_max && p.y >= bounds.y_min && p.y <= bounds.y_max;
}

/// The bounds a disc of radius `margin` may have its centre in: each side moved in by margin.
inline Bounds shrink(const Bounds& b, double margin) {
  return {b.x_min + margin, b.x_max - margin, b.y_min + margin, b.y_max - margin};
}

}  // namespace roomba_rrt::planning
