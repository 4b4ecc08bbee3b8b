#include "roomba_rrt/planning/free_point_near.h"

#include <algorithm>
#include <cmath>

#include "roomba_rrt/planning/collision_checker.h"

namespace roomba_rrt::planning {

std::optional<Point2> freePointNear(const Problem& problem, const Point2& p, double tolerance) {
  const CollisionChecker checker = collisionChecker(problem, CollisionCheck::kPoints);
  const Bounds inner = shrink(problem.bounds, robotMargin(problem));
  auto free = [&](const Point2& q) { return contains(inner, q) && checker.isFree(q); };
  if (free(p)) return p;
  if (!(tolerance > 0) || !std::isfinite(tolerance)) return std::nullopt;
  constexpr int kMaxSteps = 200;  // lattice points on each side of p, at most
  const double spacing = std::max(problem.map ? problem.map->grid().resolution : tolerance / 20,
                                  tolerance / kMaxSteps);
  const int steps = static_cast<int>(std::floor(tolerance / spacing));
  std::optional<Point2> best;
  double best_sq = 0;
  for (int dj = -steps; dj <= steps; ++dj) {
    for (int di = -steps; di <= steps; ++di) {
      const Point2 q{p.x + di * spacing, p.y + dj * spacing};
      const double d_sq = squaredDistance(p, q);
      if ((!best || d_sq < best_sq) && free(q)) best = q, best_sq = d_sq;
    }
  }
  return best;
}

}  // namespace roomba_rrt::planning
