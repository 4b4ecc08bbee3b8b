// The touch-up: once the rows are driven, the robot goes back for the floor it missed. ROS-free.
//
// Why: rows keep a clearance from everything and U-turns cut corners on arcs, so after the rows
// a few per cent of the floor is left: the corners the arcs cut, a row given up after bumps, the
// floor beside a bump, and along a wall that does not lie on the lattice's cell boundaries, a
// band within the clearance that no row sweeps. The robot knows what it swept from its own poses
// (CoveragePlanner::markSwept), so the touch-up is planned from that, not from the plan.
//
// How (TouchUp::plan(), one step per member function):
//   1. missedFloor(): the reachable floor the robot did not sweep, less the spots too small to
//      be worth going back for (8-connected pieces under min_spot_area);
//   2. unreached(): the missed floor that no drivable lattice point's disc reaches: strips
//      against a wall or a piece of furniture;
//   3. sweepStrips(): a row along each such strip, as close to it as stays free (stripRow()):
//      first at the clearance; then, for what that leaves (edge cleaning), along the wall at the
//      edge clearance, ramping in from the clearance and out to it again (unless the pass is
//      planned without edge cleaning). Strips a short gap apart are one row; a strip no free row
//      reaches whole is tried in halves;
//   4. standAtSpots(): for each spot left, the drivable lattice point whose disc covers most of
//      it, a row of no length there (the robot passes there, in any heading);
//   5. tour(): all the visits in the order of touchUpTour() (tour.h: nearest first, then 2-opt),
//      each reached by a transit.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/coverage/free_space.h"

namespace roomba_rrt::coverage {

/// One touch-up pass of `planner` for a robot at `at` that swept `swept` (CoveragePlanner::
/// touchUp() is the way to call it).
class TouchUp {
 public:
  TouchUp(const CoveragePlanner& planner, const std::vector<std::uint8_t>& swept, const Point2& at,
          double min_spot_area, bool edge_cleaning = true);

  /// The pass: its legs (transits and visits in tour order; none when nothing is missed) and the
  /// areas of the floor reachable from `at`.
  CoveragePlan plan();

  /// How long a row along a wall takes to come in from the clearance and go out to it again (m).
  static constexpr double kEdgeRamp = 0.1;
  /// A strip of this many lattice points or fewer is left to the spots' stops.
  static constexpr int kStripLength = 4;
  /// Strips along one line this many lattice points apart or closer are swept by one row.
  static constexpr int kStripGap = 16;

 private:
  void missedFloor(CoveragePlan& plan);
  void unreached();
  void sweepStrips(double clearance);
  /// Runs a short gap apart as one row; when that row is not free, each run on its own.
  void sweepStrip(const std::vector<std::vector<int>>& runs, bool vertical, double clearance);
  /// A run that no free row reaches as a whole (something stands near one end: a plant in the
  /// corner), tried in halves.
  void sweepRun(const std::vector<int>& points, bool vertical, double clearance);
  /// A row along `points`, sweeping what is missed beside it; false when no free row reaches
  /// them. Too few points to be worth a row: nothing to do (true).
  bool stripVisit(const std::vector<int>& points, bool vertical, double clearance);
  /// A row along `points` (lattice points of missed floor in order along one lattice column, or
  /// one lattice row when not `vertical`), from the first to the last, as close to them as keeps
  /// `clearance`, if the disc reaches them from there. Below the planner's clearance (edge
  /// cleaning) the row ramps in from it and out to it again (kEdgeRamp), so that it starts and
  /// ends where the robot may stand.
  std::optional<Polyline> stripRow(const std::vector<int>& points, bool vertical,
                                   double clearance) const;
  void standAtSpots();
  void tour(CoveragePlan& plan);

  const CoveragePlanner& planner_;
  const FreeSpace& space_;
  const CoverageOptions& options_;
  const std::vector<std::uint8_t>& swept_;
  const Point2 at_;
  const double min_spot_area_;
  const bool edge_cleaning_;  ///< rows along the walls at the edge clearance (step 3)
  Mask missed_;               ///< reachable floor not swept (yet: each visit clears what it sweeps)
  Mask drivable_;            ///< lattice points the robot can drive to from `at` with the clearance
  Mask uncovered_;           ///< missed floor that no drivable point's disc reaches
  std::vector<Leg> visits_;  ///< rows to drive, in either direction
};

}  // namespace roomba_rrt::coverage
