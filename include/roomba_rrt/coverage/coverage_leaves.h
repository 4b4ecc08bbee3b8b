// The cleaning tree's leaves (config/roomba_coverage_tree.xml): plan the coverage from the robot's
// pose, drive it leg by leg with the navigation's follower, resume the rest after a bump (never
// from the beginning), give up on a row after N tries, and tell when all is clean. ROS-free; they
// run in navigation::NavBt beside the navigation leaves (coverageLeaves() is the registrar).
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/navigation/nav_leaves.h"

namespace roomba_rrt::coverage {

/// The cleaning in progress, on the blackboard (the tree's key `coverage`): what is left to
/// drive and how it went. Legs before `leg` are done.
struct CoverageProgress {
  CoveragePlan plan;     ///< the plan being driven (after a resume: the rest of the previous one)
  std::size_t leg = 0;   ///< the leg being driven; legs.size() when all is done
  int tries = 0;         ///< resumes since the last row was finished (skip_after counts them)
  int bumps = 0;         ///< bumps since the cleaning started
  int skipped_rows = 0;  ///< rows given up (skip_after tries)
  /// Where: each row given up, its two ends (m), in the order they were given up.
  std::vector<std::pair<Point2, Point2>> skipped;
  /// The part of the floor `swept` marks, as of the last pass driven to its end (0..1;
  /// CoveragePlanner::sweptFraction): once done(), the coverage the cleaning reached.
  double swept_fraction = 0;
  /// The floor under the robot's disc so far, one flag per lattice point of the planner's
  /// FreeSpace (CoveragePlanner::markSwept, from the robot's poses while FollowCoverage runs).
  std::vector<std::uint8_t> swept;
  /// Touch-up passes planned so far: 0 while the rows are driven, then 1 while `plan` is the
  /// touch-up of the large spots they missed, then 2 for every spot still missed.
  int touch_ups = 0;

  /// The least spot (m²) each touch-up pass goes back for: the large ones first, so that most of
  /// the floor is clean sooner, then every spot worth it, with what the first pass left (a stop
  /// that ended a centimetre short). One pass over every spot leaves the large ones for late.
  static constexpr double kTouchUpSpotAreas[] = {0.012, CoveragePlanner::kMinSpotArea};
  static constexpr int kTouchUpPasses = static_cast<int>(std::size(kTouchUpSpotAreas));

  bool touchingUp() const { return touch_ups > 0; }
  bool done() const { return touch_ups >= kTouchUpPasses && leg >= plan.legs.size(); }
};

/// The polyline the robot still has to drive: the points of the current leg and every later one,
/// in order (a point shared by two legs once). For ~coverage_path.
Polyline remainingPath(const CoverageProgress& progress);

/// The progress on a tree's blackboard under `key` (nullptr before PlanCoverage wrote it).
const CoverageProgress* findProgress(const bt::Blackboard& board,
                                     const std::string& key = "coverage");

/// Registers, for a navigation tree (navigation::NavLeafConfig::more_leaves):
///
/// - PlanCoverage start="{pose}" coverage="{coverage}" error="{error}": plans the coverage of the
///   floor reachable from `start` (CoveragePlanner::plan) and writes it as a new progress;
///   SUCCESS, or FAILURE with `error` when there is no start pose or nothing can be cleaned from
///   it.
/// - FollowCoverage coverage="{coverage}" pose="{pose}" transit_speed="0.8" error="{error}":
///   drives the legs from `coverage.leg` on with the navigation's follower (GuardedFollower:
///   FollowPath's follower and motion guard): rows at the lab's forward_speed (RoombaParams,
///   0.5 m/s), transits at `transit_speed` (within the follower's limits; a U-turn, row, short
///   step and next row, is driven as one path, at the row's speed, its corners rounded into arcs,
///   and so are the way round an island and the segments of the loop along the walls:
///   joined_legs.h), turning in place towards each leg's start where the previous one ended. A
///   finished leg advances `coverage.leg` (a finished row also clears `tries`). It marks the floor
///   under the robot in `coverage.swept` on every tick. A row along a wall (Leg::along_wall:
///   closer than the
///   clearance) is driven on its own, never joined to the legs around it, with a guard of its own
///   (half the edge clearance, three ticks ahead). RUNNING with the command; SUCCESS when every
///   leg of the plan in hand is driven; FAILURE with `error` when the bumper is pressed
///   while it follows ("bumped", counted in `bumps`; a contact there when it starts is not a
///   bump: the robot put down against a wall drives off, where backing up would slide along the
///   wall), the robot strayed from the leg, the guard held it still ("blocked"), it made no
///   progress along the leg for 10 s (its wheels spin), or there is no progress or pose. The
///   leg it failed in stays `coverage.leg`, for ResumeCoverage.
/// - PlanTouchUp coverage="{coverage}" pose="{pose}" error="{error}": once the plan in hand is
///   driven, plans the next touch-up pass from the floor the robot marked (CoveragePlanner::
///   touchUp, touch_up.h: the corners its U-turns cut, skipped rows, the band along a wall within
///   the clearance) and writes it as the plan to follow (`coverage.touch_ups` counts the passes:
///   CoverageProgress::kTouchUpSpotAreas, the large spots first; `edge_cleaning_from`, default 1:
///   the first pass with rows along the walls at the edge clearance, the earlier ones go for the
///   spots only; `min_spot_area` (m²), default 0: the pass's own). SUCCESS, also without planning
///   while the plan in hand is not driven or every pass is planned; FAILURE when there is no
///   progress or pose. The cleaning tree follows each PlanTouchUp with a FollowCoverage.
/// - ResumeCoverage coverage="{coverage}" pose="{pose}" skip_after="3" error="{error}": the rest
///   of the plan from where the robot stands (CoveragePlanner::resume from `coverage.leg`: the
///   rest of the row it was in, or the row its transit led to). After `skip_after` resumes
///   without finishing a row, that row is given up (`skipped_rows`) and the next one is resumed
///   instead. SUCCESS with the new progress (leg 0; nothing left that can be reached: an empty
///   plan, done); FAILURE when there is no progress or pose.
/// - CoverageDone coverage="{coverage}": SUCCESS when a plan was made and every leg of it and of
///   its touch-up is driven, else FAILURE.
///
/// The leaves plan in `world` (its walls, furniture or map; the planner is built with `options`
/// when the first PlanCoverage or ResumeCoverage is, so a factory that only describes its leaves
/// or builds other trees costs nothing). The known world's motion guard (NavLeafConfig::
/// known_world) checks FollowCoverage's commands as FollowPath's.
navigation::LeafRegistrar coverageLeaves(const world::World& world,
                                         const CoverageOptions& options = {});
/// The same leaves planning with `planner` (built already: e.g. shared by several trees, or also
/// used to measure the reachable floor). Null: the leaves are only described (treeNodesModel);
/// building PlanCoverage or ResumeCoverage throws std::invalid_argument.
navigation::LeafRegistrar coverageLeaves(std::shared_ptr<const CoveragePlanner> planner);
/// The same leaves for a cleaning that goes on where another tree's stopped (a new planner on a
/// world that changed under the plan: clean_known_map.h): PlanCoverage does not plan, it writes
/// `progress` (the rest of the plan, made on `planner`; the floor swept so far on its lattice;
/// the touch-up passes done) and succeeds, unless there is nothing left at all: then it fails as
/// when nothing can be cleaned.
navigation::LeafRegistrar coverageLeaves(std::shared_ptr<const CoveragePlanner> planner,
                                         CoverageProgress progress);

}  // namespace roomba_rrt::coverage

namespace roomba_rrt::bt {
template <>
struct TypeName<coverage::CoverageProgress> {
  static std::string get() { return "CoverageProgress"; }
};
}  // namespace roomba_rrt::bt
