// The order of the touch-up's visits: which spot or row along a wall the robot goes back for
// next, and from which end. ROS-free.
//
// Nearest first (either end) from where the robot is, then shortened by 2-opt: while reversing
// a stretch of the tour (and so the direction each visit in it is driven) shortens the straight
// jumps between visits, it is reversed. Nearest first leaves the spots it passed by for a long
// way back at the end (in the dining room, the band along one wall after the far wall); 2-opt
// removes such crossings of the tour. The jumps are straight lines, a lower bound of the
// transits the planner then joins the visits with.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/coverage/free_space.h"

namespace roomba_rrt::coverage {

/// One visit of a tour: the index of a polyline given to touchUpTour(), and whether it is driven
/// from its back to its front.
struct TourStop {
  std::size_t visit = 0;
  bool reversed = false;
};

/// The tour over `visits` (each driven from one end to the other, in either direction; a single
/// point is a stop) for a robot at `start`: nearest first, then 2-opt on the straight jumps, while
/// it shortens them and at most kMaxTourChecks reversals have been tried. Every visit once.
/// Deterministic.
std::vector<TourStop> touchUpTour(const std::vector<Polyline>& visits, const Point2& start);

/// The sum of the straight jumps of `tour` over `visits` from `start` (m): to the first visit's
/// start, and from each visit's end to the next one's start.
double tourJumps(const std::vector<Polyline>& visits, const std::vector<TourStop>& tour,
                 const Point2& start);

/// The most reversals 2-opt tries (each a handful of distances; about 10 ns): a bound on the
/// time the robot waits for its touch-up, about a second. The whole of willow_full's first
/// touch-up (3,737 visits) settles after 10 rounds over every pair, 70 million tries (0.7 s).
constexpr double kMaxTourChecks = 1e8;

}  // namespace roomba_rrt::coverage
