// Smoothing a path: random shortcuts (the RRT planners' `smooth`), greedy string pulling.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/densify.h"
#include "roomba_rrt/planning/geometry.h"

namespace roomba_rrt::planning {

/// `tries` times: pick two vertices i < j of the path at random (own MATLAB stream seeded with
/// `seed`, so the result is reproducible) and, when the straight segment between them is free
/// (exact segment test, whatever the planner's mode), drop the vertices in between.
/// The endpoints never move and, by the triangle inequality, the path never gets longer.
std::vector<Point2> shortcutPath(std::vector<Point2> path, const CollisionChecker& checker,
                                 int tries, std::uint32_t seed);

/// Greedy string pulling: from the first vertex, each kept vertex is joined to the farthest later
/// vertex that `sweep(kept, vertex)` finds free for every vertex up to it (consecutive vertices
/// are taken to be joined already). The endpoints stay; by the triangle inequality the path never
/// gets longer.
template <class Sweep>
std::vector<Point2> pullString(const std::vector<Point2>& path, Sweep sweep) {
  if (path.empty()) return path;
  std::vector<Point2> out{path.front()};
  for (std::size_t i = 0; i + 1 < path.size();) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && sweep(path[i], path[j + 1])) ++j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}

namespace detail {
/// pullStringFar() and pullPolyline(): with `check_next`, the edge to the next vertex is swept too
/// when no farther one is free, and an empty path returned when it is blocked.
template <class Sweep>
std::vector<Point2> pullFar(const std::vector<Point2>& path, Sweep sweep, bool check_next) {
  if (path.empty()) return path;
  std::vector<Point2> out{path.front()};
  const std::size_t last = path.size() - 1;
  for (std::size_t i = 0; i < last;) {
    // Joined to `free` (i itself until an edge is known), not to `blocked`.
    std::size_t free = check_next ? i : i + 1, blocked = last + 1;
    for (std::size_t step = check_next ? 1 : 2; free < last; step *= 2) {
      const std::size_t j = std::min(i + step, last);
      if (!sweep(path[i], path[j])) {
        blocked = j;
        break;
      }
      free = j;
    }
    while (blocked - free > 1 && free > i) {
      const std::size_t j = free + (blocked - free) / 2;
      (sweep(path[i], path[j]) ? free : blocked) = j;
    }
    if (free == i) return {};  // the next vertex is not reachable
    out.push_back(path[free]);
    i = free;
  }
  return out;
}
}  // namespace detail

/// String pulling that looks far ahead: from each kept vertex i, the later vertex j it is joined
/// to is found by doubling (i + 2, i + 4, i + 8, ... and the last vertex) while `sweep(i, j)` is
/// free, then bisecting between the last free and the first blocked one: about 2·log2 of the
/// vertices skipped in sweeps, where pullString() sweeps to each of them. Vertices skipped need
/// not be visible from i (only the edge kept is swept), so it may cut further than pullString().
/// Consecutive vertices are taken to be joined already. The endpoints stay; the path never gets
/// longer.
template <class Sweep>
std::vector<Point2> pullStringFar(const std::vector<Point2>& path, Sweep sweep) {
  return detail::pullFar(path, sweep, false);
}

/// pullStringFar() for a polyline whose consecutive vertices are not known to be joined: every
/// edge of the answer is swept (the one to the next vertex too, when no farther one is free).
/// Empty when a vertex cannot be joined to the next one.
template <class Sweep>
std::vector<Point2> pullPolyline(const std::vector<Point2>& path, Sweep sweep) {
  return detail::pullFar(path, sweep, true);
}

/// Cuts each corner of a taut path closer: for each interior vertex v (after the corners before
/// it were cut), the parts of its two edges within `reach` of it (at most half of each edge),
/// cut into pieces of at most `spacing`, are pulled with pullStringFar(), so that the path may
/// turn between the points of its edges rather than at v only. Each cut sweeps segments about
/// 2·reach long at most, near the corner, where pulling from the previous vertex would sweep
/// the whole edge. The endpoints stay; the path never gets longer; every edge it adds is swept.
template <class Sweep>
std::vector<Point2> cutCorners(const std::vector<Point2>& path, Sweep sweep, double reach,
                               double spacing) {
  if (path.size() < 3) return path;
  std::vector<Point2> out{path.front()};
  const auto toward = [](const Point2& from, const Point2& to, double d) {
    const double length = distance(from, to);
    return length > 0 ? Point2{from.x + (to.x - from.x) * d / length,
                               from.y + (to.y - from.y) * d / length}
                      : from;
  };
  for (std::size_t k = 1; k + 1 < path.size(); ++k) {
    const Point2 u = out.back(), v = path[k], w = path[k + 1];
    const Point2 a = toward(v, u, std::min(reach, 0.5 * distance(u, v)));
    const Point2 b = toward(v, w, std::min(reach, 0.5 * distance(v, w)));
    // a and b lie on the edges u-v and v-w, so u-a and b-w are parts of free edges.
    const std::vector<Point2> cut = pullStringFar(densify({a, v, b}, spacing), sweep);
    if (a.x != u.x || a.y != u.y) out.push_back(a);
    out.insert(out.end(), cut.begin() + 1, cut.end() - 1);
    if (b.x != w.x || b.y != w.y) out.push_back(b);
  }
  out.push_back(path.back());
  return out;
}

}  // namespace roomba_rrt::planning
