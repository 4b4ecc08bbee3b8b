// The shortest path of a disc on a map, computed without the planners, as the yardstick of the
// map rows of bench/map_comparison.cpp (and where those rows draw their start/goal pairs).
//
// The lattice is the map's cell centres where the disc is free (ClearanceMap::discFree); a point
// is joined to its 16 neighbours (±1 and ±2 cells: the 8 king moves and the 8 knight moves) when
// the disc sweeps freely between them (ClearanceMap::sweepFree, exact against every blocked
// square). A* on it (Euclidean heuristic) gives the shortest lattice path; it is then
// string-pulled (each vertex joined to the farthest later vertex it sweeps freely to) and
// tightened (each interior vertex slid towards its neighbours' chord while both of its edges stay
// free, with the edges split in halves between rounds so the path can bend around an inflated
// corner's arc), every step checked by the same exact sweep test.
//
// What it is: the length of a path the disc can follow (every edge exact), so an upper bound on
// the shortest. How far above: a 16-connected lattice path is at most 1/cos(26.6°/2) − 1 = 2.8 %
// longer than a straight line (its widest gap between neighbour directions is 26.6°), which the
// string pulling removes where the line is free; what remains is the polygon around each inflated
// corner's arc (radius r, turning angle θ): with n vertices on it, at most 2nr·tan(θ/2n) − rθ,
// below 1 mm for r = 0.17 m, θ = 90° and n = 8, and any vertex left off the optimum by the
// bisection's tolerance. A narrow passage that the disc fits through but no free lattice point
// lies in (a gap within a cell of 2r) is missed: the reference then goes around, longer. And A*
// picks the way around an obstacle that is shortest on the lattice: where two ways differ by
// less than the lattice's 2.8 %, the other may be shorter once pulled straight (seen: 0.3 % on
// one of depot's pairs).
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/planning/path_smoothing.h"

namespace roomba_rrt::bench {

/// Greedy string pulling (the planning library's, path_smoothing.h).
using planning::pullString;

class DiscLattice {
 public:
  /// The lattice of `map` for a disc of `radius`: every cell centre's discFree, computed once.
  DiscLattice(const geometry::ClearanceMap& map, double radius);

  int cells() const { return static_cast<int>(free_.size()); }
  bool isFree(int cell) const { return free_[cell] != 0; }
  geometry::Point2 centre(int cell) const;

  /// The cells of the largest set of free lattice points joined by free edges.
  std::vector<int> largestComponent() const;

  /// The shortest path from lattice point `from` to `to` (free, in one component), string-pulled
  /// and tightened as described above; empty if they are not joined.
  std::vector<geometry::Point2> shortestPath(int from, int to) const;

 private:
  /// Calls visit(next) for every neighbour joined to `cell` by a free edge.
  template <class Visit>
  void forEachNeighbour(int cell, Visit visit) const;
  std::vector<geometry::Point2> latticePath(int from, int to) const;
  std::vector<geometry::Point2> pull(const std::vector<geometry::Point2>& path) const {
    return pullString(
        path, [this](const geometry::Point2& a, const geometry::Point2& b) { return sweep(a, b); });
  }
  void tighten(std::vector<geometry::Point2>& path) const;
  bool sweep(const geometry::Point2& a, const geometry::Point2& b) const {
    return map_.sweepFree(a, b, disc_);
  }

  const geometry::ClearanceMap& map_;
  geometry::ClearanceMap::Disc disc_;
  int width_, height_;
  std::vector<std::uint8_t> free_;
};

}  // namespace roomba_rrt::bench
