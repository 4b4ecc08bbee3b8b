#include "roomba_rrt/planning/nearest_neighbors/brute_force_nearest_neighbors.h"

namespace roomba_rrt::planning {

void BruteForceNearestNeighbors::clear(const Bounds& /*bounds*/,
                                       const std::vector<Point2>& /*positions*/) {
  points_.clear();
  indices_.clear();
}

void BruteForceNearestNeighbors::add(const Point2& p, int index) {
  points_.push_back(p);
  indices_.push_back(index);
}

Neighbor BruteForceNearestNeighbors::nearestNeighbor(const Point2& q) const {
  int best = -1;
  std::size_t best_slot = 0;
  double best_d2 = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d2 = squaredDistance(points_[i], q);
    if (best < 0 || d2 < best_d2 || (d2 == best_d2 && indices_[i] < best)) {
      best = indices_[i];
      best_d2 = d2;
      best_slot = i;
    }
  }
  return best < 0 ? Neighbor{} : Neighbor{best, points_[best_slot]};
}

void BruteForceNearestNeighbors::withinRadius(const Point2& q, double radius,
                                              std::vector<int>& out) const {
  out.clear();
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (squaredDistance(points_[i], q) <= radius * radius) out.push_back(indices_[i]);
  }
}

}  // namespace roomba_rrt::planning
