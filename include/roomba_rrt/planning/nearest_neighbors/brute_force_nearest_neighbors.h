// The lab's nearest-neighbour search: a linear scan over all nodes. The reference.
#pragma once

#include <vector>

#include "roomba_rrt/planning/nearest_neighbors/nearest_neighbors.h"

namespace roomba_rrt::planning {

class BruteForceNearestNeighbors final : public NearestNeighbors {
 public:
  void clear(const Bounds& bounds, const std::vector<Point2>& positions) override;
  void add(const Point2& p, int index) override;
  Neighbor nearestNeighbor(const Point2& q) const override;
  void withinRadius(const Point2& q, double radius, std::vector<int>& out) const override;
  int size() const override { return static_cast<int>(points_.size()); }

 private:
  std::vector<Point2> points_;
  std::vector<int> indices_;
};

}  // namespace roomba_rrt::planning
