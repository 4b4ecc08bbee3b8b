#include "roomba_rrt/planning/densify.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::planning {
namespace {

// Pieces an edge of `length` is cut into: at least one, none longer than `spacing`.
std::size_t piecesOf(double length, double spacing) {
  return length > 0 ? static_cast<std::size_t>(std::ceil(length / spacing)) : 1;
}

}  // namespace

std::vector<Point2> densify(const std::vector<Point2>& path, double spacing,
                            std::size_t max_points) {
  if (path.size() < 2 || !std::isfinite(spacing) || !(spacing > 0)) return path;
  const std::size_t edges = path.size() - 1;
  if (max_points <= path.size()) return path;
  // Points = 1 + the sum of every edge's pieces. Above the budget, a spacing of
  // total / (budget - 1 - edges) makes that sum at most total / spacing + edges = budget - 1.
  double total = 0, pieces = 0;
  for (std::size_t i = 0; i < edges; ++i) {
    const double length = distance(path[i], path[i + 1]);
    total += length;
    pieces += length / spacing + 1;  // an upper bound of piecesOf() that cannot overflow
  }
  if (pieces + 1 > static_cast<double>(max_points)) {
    spacing = total / static_cast<double>(max_points - 1 - edges);
  }
  std::vector<Point2> dense;
  dense.reserve(std::min(max_points, static_cast<std::size_t>(pieces) + 1));
  dense.push_back(path.front());
  for (std::size_t i = 0; i < edges; ++i) {
    const Point2 &a = path[i], &b = path[i + 1];
    const std::size_t n = piecesOf(distance(a, b), spacing);
    for (std::size_t k = 1; k < n; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(n);
      dense.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
    dense.push_back(b);
  }
  return dense;
}

}  // namespace roomba_rrt::planning
