// The nearest-neighbour structure a planner is handed: which tree node is closest to a point?
#pragma once

#include <memory>
#include <vector>

#include "roomba_rrt/planning/geometry.h"
#include "roomba_rrt/planning/planner_options.h"

namespace roomba_rrt::planning {

/// A stored point and its node index.
struct Neighbor {
  int index = -1;  ///< -1 when the structure is empty
  Point2 position;
};

/// Holds (point, node index) pairs. Every implementation returns the same answer: the node with
/// the smallest squared distance dx*dx + dy*dy, the lowest index among equals (as MATLAB's min).
class NearestNeighbors {
 public:
  virtual ~NearestNeighbors() = default;
  /// Forgets every point; points will lie inside `bounds`. `positions` is where the caller keeps
  /// the points (the tree's node array): every point added later as (p, index) must be
  /// positions[index], for as long as the structure is used. The grid reads exact coordinates
  /// from it instead of keeping a second copy of them.
  virtual void clear(const Bounds& bounds, const std::vector<Point2>& positions) = 0;
  virtual void add(const Point2& p, int index) = 0;
  /// The nearest point and its index (index -1 when empty). Returning the position saves the
  /// caller a random access into the tree at 10^6 nodes.
  virtual Neighbor nearestNeighbor(const Point2& q) const = 0;
  /// Index of the nearest point; -1 when empty.
  int nearest(const Point2& q) const { return nearestNeighbor(q).index; }
  /// Indices of all points within `radius` of q (any order).
  virtual void withinRadius(const Point2& q, double radius, std::vector<int>& out) const = 0;
  virtual int size() const = 0;
};

/// The structure named by `kind`.
std::unique_ptr<NearestNeighbors> makeNearestNeighbors(NearestSearch kind);

}  // namespace roomba_rrt::planning
