// Start/goal pairs across a whole map, for the 10^8-cell rows (map_load_bench --plans,
// big_map_probe): points where a disc is free, drawn uniformly over the map's rectangle from
// std::mt19937 seeded 2024, each pair at least half the rectangle's diagonal apart. The same
// pairs for both, in the same order.
#pragma once

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"

namespace roomba_rrt::bench {

inline std::vector<std::pair<geometry::Point2, geometry::Point2>> farApartPairs(
    const geometry::ClearanceMap& map, double radius, int count) {
  const geometry::ClearanceMap::Disc disc = map.disc(radius);
  const geometry::Rectangle e = map.grid().extent();
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> x(e.min_x, e.max_x), y(e.min_y, e.max_y);
  auto freePoint = [&] {
    for (;;) {
      const geometry::Point2 p{x(random), y(random)};
      if (map.discFree(p, disc)) return p;
    }
  };
  const double far_apart = 0.5 * std::hypot(e.max_x - e.min_x, e.max_y - e.min_y);
  std::vector<std::pair<geometry::Point2, geometry::Point2>> pairs;
  while (static_cast<int>(pairs.size()) < count) {
    const geometry::Point2 a = freePoint(), b = freePoint();
    if (geometry::distance(a, b) >= far_apart) pairs.push_back({a, b});
  }
  return pairs;
}

}  // namespace roomba_rrt::bench
