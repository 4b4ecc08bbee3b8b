// Where the robot's centre may be: the configuration space of a disc in a world (walls, circles,
// rectangles, an occupancy map), sampled on a square lattice, with the exact tests and the
// shortest paths a coverage planner needs. ROS-free.
//
// The lattice point (i, j) is the centre of the square cell i, j of edge h = resolution laid over
// the world's extent from its origin: (origin.x + (i + ½)h, origin.y + (j + ½)h). Each point is
// classed by how much room the disc has there:
//   kBlocked  the disc of the robot's radius r penetrates a wall or obstacle (world::penetrates);
//   kTight    the robot fits, but not with the planning clearance c;
//   kFree     the disc of radius R + δ is clear, with R = r + c the planning radius and
//             δ = s²/R + 10⁻⁷ m, s = h/√2 half the diagonal of a lattice square. Along a chord
//             of length 2s whose ends are at least D ≥ R from a point (a circle's centre, a
//             rectangle's or map cell's corner), the distance to that point dips by at most
//             s²/(D + √(D² − s²)) ≤ s²/R; along a flat side of an obstacle it is linear. So EVERY
//             edge between two kFree 8-neighbours keeps R from everything, exactly (obstacles
//             are convex and grown by R their only curved parts are such arcs): a lattice path
//             of kFree points is a collision-free polyline, and the shortest paths below need
//             no edge tests.
//
// segmentFree() is the exact test for any other segment: the segment against each circle and
// rectangle grown by the radius (geometry::segmentMeets), the room's walls (a convex box: both ends
// inside), and for a map every blocked cell's square that can come within the radius of it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "roomba_rrt/geometry/geometry.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::coverage {

using geometry::Point2;

/// A polyline of the robot's centre, metres.
using Polyline = std::vector<Point2>;

class FreeSpace {
 public:
  enum Class : std::uint8_t { kBlocked = 0, kTight = 1, kFree = 2 };

  /// Samples the world (world.robot().radius + clearance is the planning radius R) on a lattice of
  /// edge `resolution`. Cost: one world::penetrates per point (two near obstacles).
  FreeSpace(const world::World& world, double clearance, double resolution);

  int width() const { return width_; }
  int height() const { return height_; }
  int size() const { return width_ * height_; }
  double resolution() const { return h_; }
  /// The robot's own radius r and the planning radius R = r + clearance.
  double robotRadius() const { return robot_radius_; }
  double planningRadius() const { return radius_; }
  const world::World& world() const { return world_; }

  int index(int i, int j) const { return j * width_ + i; }
  int column(int k) const { return k % width_; }
  int row(int k) const { return k / width_; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < width_ && j < height_; }
  Class at(int k) const { return static_cast<Class>(classes_[k]); }
  Point2 point(int k) const { return point(column(k), row(k)); }
  Point2 point(int i, int j) const {
    return {origin_.x + (i + 0.5) * h_, origin_.y + (j + 0.5) * h_};
  }
  /// Whether the lattice point is floor at all (not inside a wall or an obstacle).
  bool isFloor(int k) const { return floor_[k] != 0; }
  /// Which piece of the kFree lattice (8-connected kFree points) the point belongs to: the same
  /// number for two points exactly when a lattice path of kFree points joins them; 0 for a point
  /// that is not kFree.
  std::uint32_t piece(int k) const { return pieces_[k]; }

  /// Exact: true when no point of the segment a–b puts the disc of `radius` into a wall, an
  /// obstacle or a blocked map cell (by more than world::kPenetrationTolerance, as
  /// world::penetrates; touching is refused, which errs on the safe side).
  bool segmentFree(const Point2& a, const Point2& b, double radius) const;
  bool segmentFree(const Point2& a, const Point2& b) const { return segmentFree(a, b, radius_); }

  /// The lattice point nearest `p` (within kConnectReach) of class ≥ `least` that the robot can
  /// drive to straight from `p` with its own radius r (p is where a robot stands, perhaps
  /// touching furniture). nullopt when there is none.
  std::optional<int> connect(const Point2& p, Class least) const;

  /// Shortest collision-free path (planning radius) from lattice point `from` to lattice point
  /// `to` over kFree points, 8-connected (A*, octile distance), string-pulled: each corner kept
  /// only where the straight shortcut is not free (segmentFree). nullopt when `to` cannot be
  /// reached, at once when the two lie in different pieces of the kFree lattice (a search
  /// would visit all of `from`'s piece first: 5 million points on willow_full). Ties are broken
  /// by index, so the path is deterministic.
  std::optional<Polyline> shortestPath(int from, int to) const;

  /// `path` without the corners it does not need: from each kept point, straight on to the
  /// farthest later point seen through free space (segmentFree, planning radius). Segments that
  /// are not free with the planning radius are never made, and the ones given are kept.
  Polyline shortcut(const Polyline& path) const;

  /// `path` with its corners turned on arcs of `radius` (m; none if not > 0), as a robot drives
  /// them without stopping: each arc is tangent to the two segments at its ends, which lie at most
  /// halfway along either (the radius shrinks where they would not), points at most kArcStep apart.
  /// A corner is kept where it turns less than kMinRoundedTurn, or where a chord of its arc is not
  /// free (planning radius; the arc cuts the corner, which may bring it closer to what the corner
  /// goes round). The segments of `path` are taken to be free. `passes`, when given, receives
  /// for each point of `path` the arc length along the result where it is passed: a rounded
  /// corner at its arc's middle.
  Polyline rounded(const Polyline& path, double radius,
                   std::vector<double>* passes = nullptr) const;
  /// A corner that turns less than this (rad) is kept by rounded().
  static constexpr double kMinRoundedTurn = 0.2;
  /// Largest distance between neighbouring points of a rounded() arc (m).
  static constexpr double kArcStep = 0.02;

 private:
  world::World world_;
  double robot_radius_;
  double radius_;  ///< R = robot radius + clearance
  double h_;
  Point2 origin_;
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> classes_;  ///< Class per lattice point
  /// Per lattice point, which piece of the kFree lattice (8-connected) it belongs to; 0 for
  /// the points that are not kFree.
  std::vector<std::uint32_t> pieces_;
  std::vector<std::uint8_t> floor_;  ///< 1 where the point is not inside a wall or obstacle
};

/// The largest t in [0, max] with free(t), to max/2^16, given free(0): how far a row can be moved
/// towards a wall the lattice stopped short of (by up to a step).
template <class Free>
double farthestFree(double max, Free free) {
  if (free(max)) return max;
  double lo = 0, hi = max;
  for (int k = 0; k < 16; ++k) {
    const double mid = (lo + hi) / 2;
    (free(mid) ? lo : hi) = mid;
  }
  return lo;
}

/// One flag per lattice point of a FreeSpace.
using Mask = std::vector<std::uint8_t>;

/// A leg shorter than this (m) is not worth driving: a resumed row's last millimetres, a
/// transit between points that coincide.
constexpr double kMinLegLength = 1e-6;

/// Visits the lattice points connected to `seed` (8-neighbours) for which inside(point) holds,
/// and `seed` itself, by depth-first search; `taken` marks them (and, on entry, the points not
/// to visit again).
template <class Inside, class Visit>
void forComponent(const FreeSpace& space, int seed, Inside inside, Mask& taken, Visit visit) {
  std::vector<int> frontier{seed};
  taken[seed] = 1;
  visit(seed);
  while (!frontier.empty()) {
    const int k = frontier.back();
    frontier.pop_back();
    const int i = space.column(k), j = space.row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!space.inside(i + di, j + dj)) continue;
        const int n = space.index(i + di, j + dj);
        if (!taken[n] && inside(n)) {
          taken[n] = 1;
          visit(n);
          frontier.push_back(n);
        }
      }
    }
  }
}

/// The lattice points of class ≥ `least` connected to `seed` (8-neighbours).
Mask flood(const FreeSpace& space, int seed, FreeSpace::Class least);

/// Calls visit(k) for each lattice point k closer than `radius` to the segment a–b (a disc when
/// a = b).
template <class Visit>
void forPointsNear(const FreeSpace& space, const Point2& a, const Point2& b, double radius,
                   Visit visit) {
  const double h = space.resolution();
  const Point2 o = space.point(0, 0);
  const int i0 = std::max(0, static_cast<int>(std::floor((std::min(a.x, b.x) - radius - o.x) / h)));
  const int i1 = std::min(space.width() - 1,
                          static_cast<int>(std::ceil((std::max(a.x, b.x) + radius - o.x) / h)));
  const int j0 = std::max(0, static_cast<int>(std::floor((std::min(a.y, b.y) - radius - o.y) / h)));
  const int j1 = std::min(space.height() - 1,
                          static_cast<int>(std::ceil((std::max(a.y, b.y) + radius - o.y) / h)));
  const geometry::Segment s{a, b};
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Point2 p = space.point(i, j);
      if (geometry::squaredDistance(geometry::closestPoint(s, p), p) < radius * radius) {
        visit(space.index(i, j));
      }
    }
  }
}

/// The floor `mask` marks (m²): h² per lattice point.
double area(const FreeSpace& space, const Mask& mask);

}  // namespace roomba_rrt::coverage
