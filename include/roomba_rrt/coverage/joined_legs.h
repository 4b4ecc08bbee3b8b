// Which legs of a coverage plan the robot drives as one path, without stopping between them: a
// U-turn (a row, the short step to the next row, that row), the way round an island between two
// pieces of a row, and the segments of the loop along the walls. The joined path's corners are
// rounded into arcs (FreeSpace::rounded), driven at the cleaning speed. Every other leg is driven
// on its own: the robot stops at its end, turns in place towards the next leg's start and sets off.
// FollowCoverage (coverage_leaves.h) asks this for the path to follow at each leg it starts.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/coverage/coverage_planner.h"

namespace roomba_rrt::coverage {

/// When legs are joined, and how their corners are rounded.
struct JoinRules {
  /// A transit this short (m; the step between two rows) is driven with the rows before and
  /// after it as one path: the robot takes the U-turn's two corners as arcs without stopping. The
  /// arcs cut the corners at the rows' ends, which the touch-up sweeps afterwards. Stopping at
  /// each row's end instead is most of what separates 85 % from 95 % by 1.5× the ideal time.
  static constexpr double kTransit = 0.5;
  /// The joined path's corners are rounded with this radius (m), which the robot drives at its
  /// turn-rate limit (2 rad/s: 0.28 m/s), following it with a lookahead of about the same
  /// (FollowCoverage: 0.13 m): it turns where the arc does, closer to the wall than pure pursuit
  /// cutting a sharp corner for a farther carrot. Tighter turns sweep more of the corners but
  /// take longer.
  static constexpr double kTurnRadius = 0.14;
  /// In the touch-up, whose legs go from spot to spot, legs are joined only with no turn sharper
  /// than this (rad) where they meet: a path that reverses has the follower's carrot jump behind
  /// the robot, which then turns on the spot for ever. A U-turn's corners are π/2.
  static constexpr double kMaxTurn = 2.4;
  /// The way round an island (m: half round a 1 m one, CoveragePlanner's largest) between two
  /// pieces of a row is driven with them too, at the cleaning speed: it sweeps the floor round
  /// the island.
  static constexpr double kDetour = 2.0;
};

/// The path the robot drives from one leg of a plan on.
struct JoinedLegs {
  /// The leg's points and those of the legs joined to it, corners rounded when any is joined.
  Polyline path;
  /// Arc lengths along `path` where each joined leg after the first starts: as the robot's
  /// progress passes one, that leg is the one being driven.
  std::vector<double> ends;
  /// A row, or a transit joined to the row it leads to: driven at the cleaning speed. Otherwise a
  /// transit on its own (at the transit speed).
  bool cleaning = false;
};

/// The path from `legs[first]` on (first < legs.size()): that leg, and while the next legs may be
/// joined, those too. `touching_up`: the legs are a touch-up's (CoveragePlanner::touchUp), whose
/// transits are joined only where they turn gently (JoinRules::kMaxTurn). A row along a wall
/// (Leg::along_wall) is never joined to the legs round it. `free_space` rounds the corners.
JoinedLegs joinLegs(const std::vector<Leg>& legs, std::size_t first, bool touching_up,
                    const FreeSpace& free_space);

}  // namespace roomba_rrt::coverage
