// The nearest-neighbour structure a planner is handed: which tree node is closest to a point?
#pragma once

#include <memory>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/planner_options.h"

namespace roomba_rrt::planning {

/// Holds (point, node index) pairs. Every implementation returns the same answer: the node with
/// the smallest squared distance dx*dx + dy*dy, the lowest index among equals (as MATLAB's min).
class NearestNeighbors {
 public:
  virtual ~NearestNeighbors() = default;
  /// Forgets every point; points will lie inside `bounds`.
  virtual void clear(const Bounds& bounds) = 0;
  virtual void add(const Point2& p, int index) = 0;
  /// Index of the nearest point; -1 when empty.
  virtual int nearest(const Point2& q) const = 0;
  /// Indices of all points within `radius` of q (any order).
  virtual void withinRadius(const Point2& q, double radius, std::vector<int>& out) const = 0;
  virtual int size() const = 0;
};

/// The structure named by `kind`.
std::unique_ptr<NearestNeighbors> makeNearestNeighbors(NearestSearch kind);

}  // namespace roomba_rrt::planning
