#include "roomba_rrt/mapping/map_accuracy.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace roomba_rrt::mapping {
namespace {

using geometry::Rectangle;

/// Whether the open interiors of two rectangles meet, and whether `outer` holds all of `inner`.
bool interiorsMeet(const Rectangle& a, const Rectangle& b) {
  return a.min_x < b.max_x && b.min_x < a.max_x && a.min_y < b.max_y && b.min_y < a.max_y;
}
bool holds(const Rectangle& outer, const Rectangle& inner) {
  return outer.min_x <= inner.min_x && outer.min_y <= inner.min_y && outer.max_x >= inner.max_x &&
         outer.max_y >= inner.max_y;
}

}  // namespace

CellTruth cellTruth(const world::World& world, const Rectangle& s) {
  const world::Room& room = world.room;
  const Rectangle inside{room.origin.x, room.origin.y, room.origin.x + room.width,
                         room.origin.y + room.height};
  if (!interiorsMeet(s, inside)) return CellTruth::kOccupied;  // all beyond the walls
  bool meets = !holds(inside, s);
  for (const geometry::Circle& c : room.circles) {
    if (geometry::squaredDistance(s, c.center) >= c.radius * c.radius) continue;
    meets = true;
    bool all = true;
    for (const geometry::Point2 p : {geometry::Point2{s.min_x, s.min_y},
                                     {s.max_x, s.min_y},
                                     {s.min_x, s.max_y},
                                     {s.max_x, s.max_y}}) {
      all = all && geometry::squaredDistance(p, c.center) <= c.radius * c.radius;
    }
    if (all) return CellTruth::kOccupied;
  }
  for (const Rectangle& box : room.rectangles) {
    if (!interiorsMeet(s, box)) continue;
    if (holds(box, s)) return CellTruth::kOccupied;
    meets = true;
  }
  if (room.map) {
    const geometry::OccupancyGrid& m = *room.map;
    // The map cells whose interiors meet the square's.
    const double r = m.resolution;
    const int i0 = static_cast<int>(std::floor((s.min_x - m.origin.x) / r + 1e-9));
    const int j0 = static_cast<int>(std::floor((s.min_y - m.origin.y) / r + 1e-9));
    const int i1 = static_cast<int>(std::ceil((s.max_x - m.origin.x) / r - 1e-9)) - 1;
    const int j1 = static_cast<int>(std::ceil((s.max_y - m.origin.y) / r - 1e-9)) - 1;
    bool all = true;
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const bool blocked = m.blocked(i, j);
        meets = meets || blocked;
        all = all && blocked;
      }
    }
    if (all && i0 <= i1 && j0 <= j1) return CellTruth::kOccupied;
  }
  return meets ? CellTruth::kMixed : CellTruth::kFree;
}

MapAccuracy compare(const geometry::OccupancyGrid& map, const world::World& world) {
  MapAccuracy a;
  std::vector<CellTruth> truth(map.cells.size(), CellTruth::kFree);
  std::vector<bool> computed(map.cells.size(), false);
  const auto truthAt = [&](int i, int j) {
    const std::size_t k = static_cast<std::size_t>(j) * map.width + i;
    if (!computed[k]) {
      truth[k] = cellTruth(world, map.square(i, j));
      computed[k] = true;
    }
    return truth[k];
  };
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      const std::int8_t v = map.at(i, j);
      if (v == geometry::OccupancyGrid::kUnknown) continue;
      ++a.known;
      const bool occupied = v != geometry::OccupancyGrid::kFree;
      const CellTruth t = truthAt(i, j);
      a.agreeing += occupied ? t != CellTruth::kFree : t != CellTruth::kOccupied;
      if (!occupied) {
        ++a.free_known;
        continue;
      }
      ++a.occupied;
      bool near = false;
      for (int dj = -1; dj <= 1 && !near; ++dj) {
        for (int di = -1; di <= 1 && !near; ++di) {
          near = !map.inside(i + di, j + dj) || truthAt(i + di, j + dj) != CellTruth::kFree;
        }
      }
      a.walls_off += !near;
    }
  }
  return a;
}

}  // namespace roomba_rrt::mapping
