// The grid planner ROS users pick, as a benchmark peer (issue 47): navfn, global_planner and
// Nav2's Smac 2D are all A* (or Dijkstra) on the costmap inflated by the robot's radius, moving
// between neighbouring cells. None is in Debian, so bench/map_comparison.cpp measures this one
// in their place, the way bench/roomba_switch.h stands in for a hand-written FSM.
//
// The inflated map is the planners' own: a cell centre is a node when the disc is free there
// (ClearanceMap::discFree, exact against every blocked cell's square), and two of the 8
// neighbouring centres are joined when the disc sweeps freely between them
// (ClearanceMap::sweepFree), so every path is exactly collision-free, as ours are. The edges are
// found once per map (as a costmap is inflated once, not per request) and kept as one byte of
// 8 bits per cell; plan() is the search alone. A* with costs 1 and √2 cells, the octile distance
// as the heuristic (exact on an empty grid, so admissible and consistent: a cell is final when
// it leaves the queue), ties broken towards the deeper node, its arrays allocated per query as
// navfn's and global_planner's are. Its path is the polyline through the cell centres: the
// shortest 8-connected path, up to 1/cos(22.5°) − 1 = 8.2 % longer than a straight line (5.5 %
// averaged over directions).
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/geometry/clearance_map.h"

namespace roomba_rrt::bench {

class GridAStar {
 public:
  /// The inflated grid of `map` for a disc of `radius`: every cell's 8 edges, computed once.
  GridAStar(const geometry::ClearanceMap& map, double radius);

  struct Result {
    std::vector<geometry::Point2> path;  ///< cell centres from start's cell to goal's; empty: none
    double length = 0;                   ///< m
    long expanded = 0;                   ///< cells taken from the queue
  };

  /// The shortest 8-connected path between the centres of the cells holding `start` and `goal`
  /// (both must be free nodes, else no path).
  Result plan(const geometry::Point2& start, const geometry::Point2& goal) const;

  /// The cell holding p, or −1 outside the grid.
  int cellOf(const geometry::Point2& p) const;
  geometry::Point2 centre(int cell) const;
  /// A node of the graph: the disc is free at the cell's centre.
  bool isFree(int cell) const { return free_[cell] != 0; }

 private:
  const geometry::OccupancyGrid& grid_;
  int width_, height_;
  std::vector<std::uint8_t> free_;   ///< discFree at each centre
  std::vector<std::uint8_t> edges_;  ///< bit k: the edge to neighbour k (kMoves) is free
};

}  // namespace roomba_rrt::bench
