// Whether the robot may stand at a point, or drive along a path, in the world it knows: the room's
// walls, its furniture and the robot's disc, with the planning library's exact tests.
#pragma once

#include <cstddef>

#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/planning/collision_checker.h"
#include "roomba_rrt/planning/problem.h"

namespace roomba_rrt::navigation {

/// The clearance navigation keeps on top of the robot's radius by default (m).
constexpr double kDefaultClearance = 0.05;

/// The index k of the segment path[k]-path[k + 1] nearest to `p` (the first of equally near
/// ones; 0 for a path of fewer than two points): where a robot at `p` is along the path, for
/// what is left of it.
std::size_t nearestSegment(const Path& path, const planning::Point2& p);

/// The world of a planning::Problem without its start and goal (bounds = the walls, circles and
/// rectangles = the furniture, robot_radius + clearance = the disc kept clear of both: circles
/// grown, rectangles rounded by that margin, bounds shrunk by it). A robot hugging furniture
/// (closer than the clearance, or pushed there by a bump) is not free where it stands:
/// freeStart() finds the nearest point it may plan from.
class PathChecker {
 public:
  explicit PathChecker(planning::Problem world);

  /// Whether the robot's centre may be at `p` (inside the shrunk bounds, outside every grown
  /// obstacle).
  bool isPointFree(const planning::Point2& p) const;
  /// Whether the part of `path` from point `from` on is free for the robot (a replan is due when
  /// it is not). A first point that is not free (the robot's own start, a little inside the
  /// clearance) does not count.
  bool isPathFree(const Path& path, std::size_t from) const;
  /// `start` if it is free, else the nearest free point within 0.25 m of it (`start` when none
  /// is): where a plan for a robot hugging furniture starts.
  planning::Point2 freeStart(const planning::Point2& start) const;
  /// Whether the robot's disc fits between the walls at all.
  bool fits() const;

  const planning::Problem& world() const { return world_; }

 private:
  planning::Problem world_;
  planning::CollisionChecker checker_;  ///< exact tests against the grown obstacles
  planning::Bounds shrunk_;             ///< bounds shrunk by radius + clearance
};

}  // namespace roomba_rrt::navigation
