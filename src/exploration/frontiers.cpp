#include "roomba_rrt/exploration/frontiers.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace roomba_rrt::exploration {

namespace {

using geometry::OccupancyGrid;

constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

bool isFrontierCell(const OccupancyGrid& map, int i, int j) {
  if (map.at(i, j) != OccupancyGrid::kFree) return false;
  for (int k = 0; k < 4; ++k) {
    const int ni = i + kDx[k], nj = j + kDy[k];
    if (map.inside(ni, nj) && map.at(ni, nj) == OccupancyGrid::kUnknown) return true;
  }
  return false;
}

geometry::Point2 centre(const OccupancyGrid& map, int i, int j) {
  return {map.origin.x + (i + 0.5) * map.resolution, map.origin.y + (j + 0.5) * map.resolution};
}

/// Dijkstra over the cells' centres, 8-connected, distances in cells: from `sources` (at 0)
/// through the cells `enter(i, j)` lets in, no farther than `reach`. `reached(from, to)` is told
/// each time a cell gets a shorter way (from the cell it is reached from); `settled(cell, d)` is
/// called for each cell in the order of its distance and ends the search by returning true.
template <class Enter, class Reached, class Settled>
void dijkstra(const OccupancyGrid& map, const std::vector<int>& sources, double reach, Enter enter,
              Reached reached, Settled settled) {
  std::vector<double> distance(map.cells.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (const int cell : sources) {
    distance[cell] = 0;
    open.push({0.0, cell});
  }
  while (!open.empty()) {
    const auto [d, cell] = open.top();
    open.pop();
    if (d > distance[cell]) continue;
    if (settled(cell, d)) return;
    const int ci = cell % map.width, cj = cell / map.width;
    for (int k = 0; k < 8; ++k) {
      const int ni = ci + kDx[k], nj = cj + kDy[k];
      if (!map.inside(ni, nj) || !enter(ni, nj)) continue;
      const int n = nj * map.width + ni;
      const double nd = d + (k < 4 ? 1.0 : M_SQRT2);
      if (nd <= reach && nd < distance[n]) {
        distance[n] = nd;
        reached(cell, n);
        open.push({nd, n});
      }
    }
  }
}

/// For every cell, the frontier within `reach` cells of it over free floor (−1: none; where
/// several are, the nearest). Over free cells only, so that a frontier is not "in view" through a
/// wall: within a few cells the way over free floor stands for the line of sight.
std::vector<int> frontierInView(const OccupancyGrid& map, const std::vector<Frontier>& frontiers,
                                double reach) {
  std::vector<int> in_view(map.cells.size(), -1);
  std::vector<int> sources;
  for (int f = 0; f < static_cast<int>(frontiers.size()); ++f) {
    for (const int cell : frontiers[f].cells) {
      in_view[cell] = f;
      sources.push_back(cell);
    }
  }
  dijkstra(
      map, sources, reach, [&map](int i, int j) { return map.at(i, j) == OccupancyGrid::kFree; },
      [&in_view](int from, int to) { in_view[to] = in_view[from]; },
      [](int, double) { return false; });
  return in_view;
}

}  // namespace

std::vector<Frontier> findFrontiers(const OccupancyGrid& map, int min_cells) {
  std::vector<std::uint8_t> seen(map.cells.size(), 0);
  std::vector<Frontier> frontiers;
  std::vector<int> stack;
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      const std::size_t first = static_cast<std::size_t>(j) * map.width + i;
      if (seen[first] || !isFrontierCell(map, i, j)) continue;
      // The 8-connected piece of frontier cells holding (i, j).
      Frontier frontier;
      seen[first] = 1;
      stack.assign(1, static_cast<int>(first));
      while (!stack.empty()) {
        const int cell = stack.back();
        stack.pop_back();
        frontier.cells.push_back(cell);
        const int ci = cell % map.width, cj = cell / map.width;
        for (int k = 0; k < 8; ++k) {
          const int ni = ci + kDx[k], nj = cj + kDy[k];
          if (!map.inside(ni, nj)) continue;
          const std::size_t n = static_cast<std::size_t>(nj) * map.width + ni;
          if (seen[n] || !isFrontierCell(map, ni, nj)) continue;
          seen[n] = 1;
          stack.push_back(static_cast<int>(n));
        }
      }
      if (static_cast<int>(frontier.cells.size()) < min_cells) continue;
      for (const int cell : frontier.cells) {
        const geometry::Point2 c = centre(map, cell % map.width, cell / map.width);
        frontier.centroid.x += c.x / frontier.cells.size();
        frontier.centroid.y += c.y / frontier.cells.size();
      }
      frontiers.push_back(std::move(frontier));
    }
  }
  return frontiers;
}

std::optional<FrontierGoal> nearestFrontier(const geometry::ClearanceMap& known,
                                            const geometry::Point2& from,
                                            const std::vector<Frontier>& frontiers,
                                            const FrontierOptions& options) {
  const OccupancyGrid& map = known.grid();
  const int fi = map.column(from.x), fj = map.row(from.y);
  if (frontiers.empty() || !map.inside(fi, fj)) return std::nullopt;
  const std::vector<int> in_view =
      frontierInView(map, frontiers, options.view_distance / map.resolution);
  const geometry::ClearanceMap::Disc disc = known.disc(options.robot_radius);
  // 0 not looked at, 1 drivable, 2 not drivable: each cell's disc test runs once.
  std::vector<std::uint8_t> drivable(map.cells.size(), 0);
  auto isDrivable = [&](int i, int j) {
    std::uint8_t& d = drivable[static_cast<std::size_t>(j) * map.width + i];
    if (d == 0) d = known.discFree(centre(map, i, j), disc) ? 1 : 2;
    return d == 1;
  };
  // The robot's own cell is where it stands even when its disc touches something there.
  const int start = fj * map.width + fi;
  std::optional<FrontierGoal> goal;
  dijkstra(
      map, {start}, std::numeric_limits<double>::infinity(), isDrivable, [](int, int) {},
      [&](int cell, double d) {
        const int ci = cell % map.width, cj = cell / map.width;
        if (in_view[cell] < 0 || (cell != start && !isDrivable(ci, cj))) return false;
        goal = FrontierGoal{centre(map, ci, cj), d * map.resolution, in_view[cell]};
        return true;
      });
  return goal;
}

}  // namespace roomba_rrt::exploration
