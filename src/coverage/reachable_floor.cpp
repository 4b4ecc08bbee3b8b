#include "roomba_rrt/coverage/reachable_floor.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace roomba_rrt::coverage {

namespace {

/// The angle between neighbouring directions of kDirections (rad).
const double kTurnStep = 2 * std::acos(-1.0) / kReachDirections;

/// The kReachDirections directions, kTurnStep apart from +x, computed once (not a sine and a
/// cosine per centre tried).
const std::array<Point2, kReachDirections> kDirections = [] {
  std::array<Point2, kReachDirections> out;
  for (int d = 0; d < kReachDirections; ++d) {
    out[d] = {std::cos(d * kTurnStep), std::sin(d * kTurnStep)};
  }
  return out;
}();

}  // namespace

Mask floorReachedFrom(const FreeSpace& space, const Mask& region) {
  const double h = space.resolution();
  const double r = space.robotRadius();
  const world::World& world = space.world();
  Mask reached = region, tried(space.size(), 0);
  // near: within kNearRegion steps of the region. A free centre that near it is in the same free
  // space: a wall between them, grown by r, would be 2r thick.
  Mask near = region;
  for (int k = 0; k < space.size(); ++k) {
    if (!region[k]) continue;
    const int i = space.column(k), j = space.row(k);
    if (i > 0 && j > 0 && i + 1 < space.width() && j + 1 < space.height() && region[k - 1] &&
        region[k + 1] && region[k - space.width()] && region[k + space.width()]) {
      continue;  // not on the boundary
    }
    const Point2 p = space.point(k);
    forPointsNear(space, p, p, r, [&](int n) { reached[n] = 1; });
    for (int dj = -kNearRegion; dj <= kNearRegion; ++dj) {
      for (int di = -kNearRegion; di <= kNearRegion; ++di) {
        if (space.inside(i + di, j + dj)) near[space.index(i + di, j + dj)] = 1;
      }
    }
  }
  // Whether a free centre near the region lies at r from x (just under: the disc sweeps what
  // lies closer than r), trying the direction of `towards` first, then turning either way.
  const Point2 origin = space.point(0, 0);
  const double reach = r * (1 - 1e-9);
  // `towards` is a lattice neighbour: each first direction (a multiple of 45°) is one of
  // kDirections, and so is every turn from it.
  auto reachedFrom = [&](const Point2& x, const Point2& towards) {
    const int first =
        static_cast<int>(std::lround(std::atan2(towards.y - x.y, towards.x - x.x) / kTurnStep));
    for (int d = 0; d < kReachDirections; ++d) {
      const int turn = (d + 1) / 2 * (d % 2 ? 1 : -1);  // 0, +1, −1, +2, −2, …
      const Point2 u =
          kDirections[((first + turn) % kReachDirections + kReachDirections) % kReachDirections];
      const Point2 c{x.x + reach * u.x, x.y + reach * u.y};
      const int i = static_cast<int>(std::lround((c.x - origin.x) / h));
      const int j = static_cast<int>(std::lround((c.y - origin.y) / h));
      if (space.inside(i, j) && near[space.index(i, j)] && !world::penetrates(world, r, c.x, c.y)) {
        return true;
      }
    }
    return false;
  };
  // Outwards from what the discs reach, one lattice step at a time: each floor point next to a
  // reached one, tried once, looking back towards that one first.
  std::vector<std::pair<int, int>> next;  // (point, its reached neighbour)
  auto push = [&](int k) {
    const int i = space.column(k), j = space.row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!space.inside(i + di, j + dj)) continue;
        const int n = space.index(i + di, j + dj);
        if (reached[n] || tried[n] || !space.isFloor(n)) continue;
        tried[n] = 1;
        next.emplace_back(n, k);
      }
    }
  };
  for (int k = 0; k < space.size(); ++k) {
    if (reached[k] && space.isFloor(k)) push(k);
  }
  while (!next.empty()) {
    const auto [n, from] = next.back();
    next.pop_back();
    if (reachedFrom(space.point(n), space.point(from))) {
      reached[n] = 1;
      push(n);
    }
  }
  for (int k = 0; k < space.size(); ++k) reached[k] = reached[k] && space.isFloor(k);
  return reached;
}

}  // namespace roomba_rrt::coverage
