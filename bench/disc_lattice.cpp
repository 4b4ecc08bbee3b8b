#include "disc_lattice.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace roomba_rrt::bench {
namespace {

using geometry::Point2;

/// The 16 neighbours: king moves, then knight moves.
constexpr int kOffsets[16][2] = {{1, 0},  {-1, 0},  {0, 1},  {0, -1}, {1, 1},  {1, -1},
                                 {-1, 1}, {-1, -1}, {2, 1},  {2, -1}, {-2, 1}, {-2, -1},
                                 {1, 2},  {1, -2},  {-1, 2}, {-1, -2}};

constexpr int kTightenRounds = 4;  // rounds of splitting the edges and sliding the vertices
constexpr int kSlideSweeps = 8;    // slides of every vertex per round
constexpr int kBisections = 12;    // how far a slide is bisected (1/4096 of the way)

Point2 lerp(const Point2& a, const Point2& b, double t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

}  // namespace

DiscLattice::DiscLattice(const geometry::ClearanceMap& map, double radius)
    : map_(map),
      disc_(map.disc(radius)),
      width_(map.grid().width),
      height_(map.grid().height),
      free_(static_cast<std::size_t>(width_) * height_) {
  for (int cell = 0; cell < cells(); ++cell) free_[cell] = map_.discFree(centre(cell), disc_);
}

Point2 DiscLattice::centre(int cell) const {
  const geometry::OccupancyGrid& g = map_.grid();
  return {g.origin.x + (cell % width_ + 0.5) * g.resolution,
          g.origin.y + (cell / width_ + 0.5) * g.resolution};
}

template <class Visit>
void DiscLattice::forEachNeighbour(int cell, Visit visit) const {
  const int i = cell % width_, j = cell / width_;
  for (const auto& o : kOffsets) {
    const int ni = i + o[0], nj = j + o[1];
    if (ni < 0 || nj < 0 || ni >= width_ || nj >= height_) continue;
    const int next = nj * width_ + ni;
    if (isFree(next) && sweep(centre(cell), centre(next))) visit(next);
  }
}

std::vector<int> DiscLattice::largestComponent() const {
  std::vector<int> label(free_.size(), -1);
  std::vector<int> best, members, stack;
  for (int seed = 0; seed < cells(); ++seed) {
    if (!isFree(seed) || label[seed] >= 0) continue;
    members.clear();
    stack.assign(1, seed);
    label[seed] = seed;
    while (!stack.empty()) {
      const int cell = stack.back();
      stack.pop_back();
      members.push_back(cell);
      forEachNeighbour(cell, [&](int next) {
        if (label[next] < 0) {
          label[next] = seed;
          stack.push_back(next);
        }
      });
    }
    if (members.size() > best.size()) std::swap(best, members);
  }
  std::sort(best.begin(), best.end());
  return best;
}

std::vector<Point2> DiscLattice::latticePath(int from, int to) const {
  // A*: g = the lattice path length so far, the Euclidean distance to `to` as the heuristic
  // (admissible and consistent, so a cell is final when it leaves the queue).
  std::vector<double> g(free_.size(), std::numeric_limits<double>::infinity());
  std::vector<int> parent(free_.size(), -1);
  std::vector<std::uint8_t> done(free_.size(), 0);
  using Entry = std::pair<double, int>;  // f = g + h, cell
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  const Point2 goal = centre(to);
  g[from] = 0;
  open.push({geometry::distance(centre(from), goal), from});
  while (!open.empty()) {
    const int cell = open.top().second;
    open.pop();
    if (done[cell]) continue;
    done[cell] = 1;
    if (cell == to) break;
    const Point2 c = centre(cell);
    forEachNeighbour(cell, [&](int next) {
      const Point2 n = centre(next);
      const double through = g[cell] + geometry::distance(c, n);
      if (through < g[next]) {
        g[next] = through;
        parent[next] = cell;
        open.push({through + geometry::distance(n, goal), next});
      }
    });
  }
  if (!done[to]) return {};
  std::vector<Point2> path;
  for (int cell = to; cell >= 0; cell = parent[cell]) path.push_back(centre(cell));
  std::reverse(path.begin(), path.end());
  return path;
}

void DiscLattice::tighten(std::vector<Point2>& path) const {
  for (int round = 0; round < kTightenRounds; ++round) {
    // Split every edge in two (its halves are free: they are parts of it), so a bend can spread
    // over more vertices around an arc.
    std::vector<Point2> split{path.front()};
    for (std::size_t k = 1; k < path.size(); ++k) {
      split.push_back(lerp(path[k - 1], path[k], 0.5));
      split.push_back(path[k]);
    }
    path = std::move(split);
    // Slide each interior vertex towards the midpoint of its neighbours as far as both of its
    // edges stay free (bisected): each accepted slide shortens the path.
    for (int sweep_round = 0; sweep_round < kSlideSweeps; ++sweep_round) {
      for (std::size_t k = 1; k + 1 < path.size(); ++k) {
        const Point2 target = lerp(path[k - 1], path[k + 1], 0.5);
        double lo = 0, hi = 1;
        for (int b = 0; b < kBisections; ++b) {
          const double t = b == 0 ? 1 : 0.5 * (lo + hi);  // all the way first
          const Point2 p = lerp(path[k], target, t);
          if (sweep(path[k - 1], p) && sweep(p, path[k + 1])) {
            lo = t;
            if (t == 1) break;
          } else {
            hi = t;
          }
        }
        path[k] = lerp(path[k], target, lo);
      }
    }
    path = pull(path);
  }
}

std::vector<Point2> DiscLattice::shortestPath(int from, int to) const {
  std::vector<Point2> path = latticePath(from, to);
  if (path.size() < 2) return path;
  path = pull(path);
  tighten(path);
  return path;
}

}  // namespace roomba_rrt::bench
