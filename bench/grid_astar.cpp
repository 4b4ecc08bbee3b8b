#include "grid_astar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace roomba_rrt::bench {
namespace {

using geometry::Point2;

// The 8 moves; move k and move k ^ 1 are opposite.
constexpr int kMoves[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
constexpr double kDiagonal = 1.4142135623730951;

/// The octile distance in cells: the 8-connected path length on an empty grid.
double octile(int di, int dj) {
  const int a = std::abs(di), b = std::abs(dj);
  return std::max(a, b) + (kDiagonal - 1) * std::min(a, b);
}

}  // namespace

GridAStar::GridAStar(const geometry::ClearanceMap& map, double radius)
    : grid_(map.grid()),
      width_(grid_.width),
      height_(grid_.height),
      free_(static_cast<std::size_t>(width_) * height_),
      edges_(free_.size(), 0) {
  const geometry::ClearanceMap::Disc disc = map.disc(radius);
  for (std::size_t cell = 0; cell < free_.size(); ++cell) {
    free_[cell] = map.discFree(centre(static_cast<int>(cell)), disc);
  }
  // Each edge is swept once, from the cell where its move has an even index, and set both ways.
  for (int cell = 0; cell < static_cast<int>(free_.size()); ++cell) {
    if (!free_[cell]) continue;
    const int i = cell % width_, j = cell / width_;
    for (int k = 0; k < 8; k += 2) {
      const int ni = i + kMoves[k][0], nj = j + kMoves[k][1];
      if (!grid_.inside(ni, nj)) continue;
      const int next = nj * width_ + ni;
      if (free_[next] && map.sweepFree(centre(cell), centre(next), disc)) {
        edges_[cell] |= 1u << k;
        edges_[next] |= 1u << (k ^ 1);
      }
    }
  }
}

int GridAStar::cellOf(const Point2& p) const {
  const int i = static_cast<int>(std::floor((p.x - grid_.origin.x) / grid_.resolution));
  const int j = static_cast<int>(std::floor((p.y - grid_.origin.y) / grid_.resolution));
  return grid_.inside(i, j) ? j * width_ + i : -1;
}

Point2 GridAStar::centre(int cell) const {
  return {grid_.origin.x + (cell % width_ + 0.5) * grid_.resolution,
          grid_.origin.y + (cell / width_ + 0.5) * grid_.resolution};
}

GridAStar::Result GridAStar::plan(const Point2& start, const Point2& goal) const {
  Result result;
  const int from = cellOf(start), to = cellOf(goal);
  if (from < 0 || to < 0 || !free_[from] || !free_[to]) return result;
  const int gi = to % width_, gj = to / width_;
  const auto heuristic = [&](int cell) { return octile(cell % width_ - gi, cell / width_ - gj); };

  std::vector<double> g(free_.size(), std::numeric_limits<double>::infinity());
  std::vector<int> parent(free_.size(), -1);
  // (f, −g, cell): the smallest f first, and of equal f the largest g (the deeper node).
  using Entry = std::pair<std::pair<double, double>, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  g[from] = 0;
  open.push({{heuristic(from), 0.0}, from});
  while (!open.empty()) {
    const auto [key, cell] = open.top();
    open.pop();
    if (-key.second > g[cell]) continue;  // a stale entry: the cell was reached shorter since
    ++result.expanded;
    if (cell == to) break;
    const int i = cell % width_, j = cell / width_;
    for (int k = 0; k < 8; ++k) {
      if (!(edges_[cell] & (1u << k))) continue;
      const int next = (j + kMoves[k][1]) * width_ + i + kMoves[k][0];
      const double through = g[cell] + (k < 4 ? 1.0 : kDiagonal);
      if (through < g[next]) {
        g[next] = through;
        parent[next] = cell;
        open.push({{through + heuristic(next), -through}, next});
      }
    }
  }
  if (!std::isfinite(g[to])) return result;
  for (int cell = to; cell >= 0; cell = parent[cell]) result.path.push_back(centre(cell));
  std::reverse(result.path.begin(), result.path.end());
  result.length = g[to] * grid_.resolution;
  return result;
}

}  // namespace roomba_rrt::bench
