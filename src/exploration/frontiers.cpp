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

/// Dijkstra over the cells' centres, 8-connected, distances in cells: from `sources` (cells and
/// their distances to start with)
/// through the cells `enter(i, j)` lets in, no farther than `reach`. `reached(from, to)` is told
/// each time a cell gets a shorter way (from the cell it is reached from); `settled(cell, d)` is
/// called for each cell in the order of its distance and ends the search by returning true.
template <class Enter, class Reached, class Settled>
void dijkstra(const OccupancyGrid& map, const std::vector<std::pair<int, double>>& sources,
              double reach, Enter enter, Reached reached, Settled settled) {
  std::vector<double> distance(map.cells.size(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  for (const auto& [cell, d] : sources) {
    distance[cell] = std::min(distance[cell], d);
    open.push({d, cell});
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
  std::vector<std::pair<int, double>> sources;
  for (int f = 0; f < static_cast<int>(frontiers.size()); ++f) {
    for (const int cell : frontiers[f].cells) {
      in_view[cell] = f;
      sources.push_back({cell, 0.0});
    }
  }
  dijkstra(
      map, sources, reach, [&map](int i, int j) { return map.at(i, j) == OccupancyGrid::kFree; },
      [&in_view](int from, int to) { in_view[to] = in_view[from]; },
      [](int, double) { return false; });
  return in_view;
}

/// Whether the straight line from the centre of cell (i0, j0) to that of (i1, j1) crosses only
/// free cells of `map` before it enters (i1, j1) (sampled every fifth of a cell): a ray from the
/// first would reach the second.
bool clearLine(const OccupancyGrid& map, int i0, int j0, int i1, int j1) {
  const int samples = static_cast<int>(std::ceil(5 * std::hypot(i1 - i0, j1 - j0)));
  for (int s = 1; s < samples; ++s) {
    const double t = static_cast<double>(s) / samples;
    const int i = static_cast<int>(std::floor(i0 + 0.5 + t * (i1 - i0)));
    const int j = static_cast<int>(std::floor(j0 + 0.5 + t * (j1 - j0)));
    if (i == i1 && j == j1) return true;
    if (map.at(i, j) != OccupancyGrid::kFree) return false;
  }
  return true;
}

/// Whether a ray from cell (i, j) reaches an unknown cell beside frontier cell (fi, fj): the
/// robot standing there sees what lies beyond the frontier.
bool seesBeyond(const OccupancyGrid& map, int i, int j, int fi, int fj) {
  for (int k = 0; k < 4; ++k) {
    const int ui = fi + kDx[k], uj = fj + kDy[k];
    if (map.inside(ui, uj) && map.at(ui, uj) == OccupancyGrid::kUnknown &&
        clearLine(map, i, j, ui, uj)) {
      return true;
    }
  }
  return false;
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
  return nearestFrontier(known, known.grid(), from, frontiers, options);
}

std::optional<FrontierGoal> nearestFrontier(const geometry::ClearanceMap& known,
                                            const OccupancyGrid& sight,
                                            const geometry::Point2& from,
                                            const std::vector<Frontier>& frontiers,
                                            const FrontierOptions& options) {
  const OccupancyGrid& map = known.grid();
  const int fi = map.column(from.x), fj = map.row(from.y);
  if (frontiers.empty() || !map.inside(fi, fj) || sight.width != map.width ||
      sight.height != map.height) {
    return std::nullopt;
  }
  const double reach = options.view_distance / map.resolution;
  const std::vector<int> in_view = frontierInView(sight, frontiers, reach);
  // Whether a cell of frontier f within reach is in plain sight from cell (i, j).
  std::vector<int> frontier_of(map.cells.size(), -1);
  for (int f = 0; f < static_cast<int>(frontiers.size()); ++f) {
    for (const int cell : frontiers[f].cells) frontier_of[cell] = f;
  }
  const int r = static_cast<int>(std::floor(reach));
  auto seesFrontier = [&](int i, int j, int f) {
    for (int cj = std::max(0, j - r); cj <= std::min(map.height - 1, j + r); ++cj) {
      for (int ci = std::max(0, i - r); ci <= std::min(map.width - 1, i + r); ++ci) {
        if (frontier_of[cj * map.width + ci] == f && std::hypot(ci - i, cj - j) <= reach &&
            seesBeyond(sight, i, j, ci, cj)) {
          return true;
        }
      }
    }
    return false;
  };
  const geometry::ClearanceMap::Disc disc = known.disc(options.robot_radius);
  // 0 not looked at, 1 drivable, 2 not drivable: each cell's disc test runs once.
  std::vector<std::uint8_t> drivable(map.cells.size(), 0);
  auto isDrivable = [&](int i, int j) {
    std::uint8_t& d = drivable[static_cast<std::size_t>(j) * map.width + i];
    if (d == 0) d = known.discFree(centre(map, i, j), disc) ? 1 : 2;
    return d == 1;
  };
  // From the robot's own cell; when its disc (with the margin) touches something there, from
  // the drivable cells within a radius of it, as far as they are: it gets there first.
  const int start = fj * map.width + fi;
  std::vector<std::pair<int, double>> sources = {{start, 0.0}};
  const int around = static_cast<int>(std::ceil(options.robot_radius / map.resolution));
  if (!isDrivable(fi, fj)) {
    for (int j = fj - around; j <= fj + around; ++j) {
      for (int i = fi - around; i <= fi + around; ++i) {
        if (map.inside(i, j) && std::hypot(i - fi, j - fj) <= around && isDrivable(i, j)) {
          sources.push_back({j * map.width + i, std::hypot(i - fi, j - fj)});
        }
      }
    }
  }
  std::optional<FrontierGoal> goal;
  dijkstra(
      map, sources, std::numeric_limits<double>::infinity(), isDrivable, [](int, int) {},
      [&](int cell, double d) {
        const int ci = cell % map.width, cj = cell / map.width;
        if (in_view[cell] < 0 || (cell != start && !isDrivable(ci, cj)) ||
            !seesFrontier(ci, cj, in_view[cell])) {
          return false;
        }
        goal = FrontierGoal{centre(map, ci, cj), d * map.resolution, in_view[cell]};
        return true;
      });
  return goal;
}

}  // namespace roomba_rrt::exploration
