// The way round first, then the path: A* over a map's regions picks which way round the
// obstacles to go, and string pulling with exact sweeps makes that way taut (issue 47: a path as
// short as ROS's grid planners' in a fraction of their time).
//
// Why: a grid planner (navfn, global_planner, Smac 2D: A* or Dijkstra on the inflated grid)
// expands every cell whose cost plus heuristic is below its path's, often a large part of the
// map, and its 8-connected path is a few per cent longer than the shortest. An RRT finds a path
// in a fraction of that time, but takes whichever way round the obstacles its trees met through,
// and no smoothing moves a path into another corridor. Here the way round comes from a search of
// the map's regions (grid_regions.h: the parts of each 4 × 4-cell block, a sixteenth of the
// cells or fewer), and what makes it short is pulling it taut in the plane, not along cells:
//
//   1. The straight segment, when the disc sweeps freely along it, is the answer.
//   2. Lazy Theta* over the regions, from the start's to the goal's: A* (costs: the distance
//      between the regions' points; heuristic: the distance to the goal's point), but a region
//      may take its predecessor's parent as its own when the straight line between their points
//      (at most 8 blocks long) crosses clear blocks only (GridRegions::clearBetween(): a look-up
//      per block), so that across open floor the way round is chosen by straight-line lengths,
//      not by steps between neighbouring blocks (up to 8 % longer, by direction).
//   3. The start, the points of the regions the way turns at, the goal, pulled taut
//      (pullPolyline(): from each kept point, the farthest later one the disc sweeps to, found by
//      doubling and bisection).
//   4. Only where a region's point does not see the next one (a doorway narrower than a block,
//      clutter): A* over the fine graph's cells in the blocks of those regions and their 8
//      neighbours (costs 1 and √2 cells, the octile distance as heuristic), whose path the
//      regions guarantee (joined regions are joined by fine edges), then pulled the same way.
//   5. Each corner cut closer (cutCorners(): the parts of its two edges within 8 cells of it, in
//      2-cell pieces, pulled), then pulled once more, so that corners are cut between the
//      points, not only at them.
//
// Every edge of the answer is swept exactly by ClearanceMap::sweepFree, or is an edge of the fine
// graph (swept when it was built), so the path is as collision-free as the RRT planners'. By the
// triangle inequality pulling never lengthens a path. Deterministic: no random numbers.
#pragma once

#include "roomba_rrt/planning/grid_regions.h"
#include "roomba_rrt/planning/plan_result.h"
#include "roomba_rrt/planning/stop_condition.h"

namespace roomba_rrt::planning {

/// Plans from `start` to `goal` for the disc of regions.radius() (both must be where it is free,
/// else no path and a message naming the field). `iterations` in the result counts the regions
/// and cells taken from the queues; the tree is left empty. Asks `stop` once per region or cell
/// taken (nullptr: never stops).
PlanResult solveRegionAStar(const GridRegions& regions, const Point2& start, const Point2& goal,
                            StopCondition* stop = nullptr);

}  // namespace roomba_rrt::planning
