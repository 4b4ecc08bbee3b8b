// The navigation tree's leaves (Nav2's names where the meaning is the same): ComputePath,
// FollowPath, BackUp, Spin, GoalUpdated, and the conditions and goal-bookkeeping leaves the tree
// files use. ROS-free; NavBt (nav_bt.h) is the behaviour around them.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "roomba_rrt/navigation/motion_guard.h"
#include "roomba_rrt/navigation/path_checker.h"
#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/navigation/path_planner.h"

namespace roomba_rrt::bt {
template <>
struct TypeName<robot::Pose2D> {
  static std::string get() { return "Pose2D"; }
};
template <>
struct TypeName<navigation::Path> {
  static std::string get() { return "Path"; }
};
/// A literal pose: "x;y;theta" (three finite numbers).
template <>
struct LiteralParser<robot::Pose2D> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, robot::Pose2D& out);
};
}  // namespace roomba_rrt::bt

namespace roomba_rrt::navigation {

/// How a navigation goal ended (what a move_base client is told).
enum class GoalOutcome : std::uint8_t { kNone, kActive, kSucceeded, kAborted };
const char* toString(GoalOutcome outcome);

/// The data the navigation leaves share besides the blackboard: the lab's context (bumper in,
/// command out, the leaf's name), the previous tick's command (the follower's acceleration
/// limits start from it), and the outcome of the current goal.
struct NavContext : behavior::RoombaContext {
  explicit NavContext(std::uint32_t seed) : behavior::RoombaContext(seed) {}
  robot::Velocity previous_cmd;
  GoalOutcome outcome = GoalOutcome::kNone;
  std::string message;  ///< why the goal was aborted
  /// FollowPath's limits and tolerances when they were changed after the tree was built
  /// (NavBt::setFollowerParams), and how often: FollowPath takes them up on its next tick.
  FollowerParams follower;
  std::uint64_t follower_version = 0;
  /// The factor on the cleaning's speeds for the latency of the loop (LatencySpeedPolicy): 1 on
  /// time. NavBt sets it each tick; FollowCoverage takes it up at once.
  double speed_scale = 1;
};

/// Makes one planner per ComputePath leaf (each leaf has its own pending plan).
using PlannerFactory = std::function<std::unique_ptr<PathPlanner>()>;

struct NavLeafConfig;
/// Registers further leaves on the factory of a navigation tree, beside the navigation leaves,
/// with the same configuration and context (coverage::coverageLeaves: the cleaning leaves).
using LeafRegistrar = std::function<void(bt::TreeFactory&, const NavLeafConfig&, NavContext&)>;

/// What the navigation leaves need to be built.
struct NavLeafConfig {
  behavior::RoombaParams params;  ///< rate (ticks per second) and the Spin's default speed
  FollowerParams follower;        ///< FollowPath's limits and tolerances
  PlannerFactory planners;        ///< ComputePath's planners
  /// The walls and furniture the robot knows: IsPathValid and ComputePath check paths against
  /// them, and FollowPath never lets the robot touch them (MotionGuard). Null: every path counts
  /// as free and FollowPath's commands go out unchecked.
  std::shared_ptr<const PathChecker> known_world;
  /// More leaves, registered after the navigation leaves (e.g. coverage::coverageLeaves).
  std::vector<LeafRegistrar> more_leaves;
  /// s, how old the pose is by the time the command computed from it drives the robot (over
  /// ROS: a tick; 0 in-process). NavBt drives the pose forward over it (PosePredictor).
  double pose_latency = 0;
};

/// The motion guard of the known world keeping `margin` (FollowPath's: 1 cm), at the follower's
/// rate and acceleration: null without a known world.
std::shared_ptr<const MotionGuard> knownWorldGuard(const NavLeafConfig& config,
                                                   double margin = 0.01, int ticks = 1);

/// Registers, on `factory`:
///
/// - ComputePath start="{pose}" goal="{goal}" path="{path}" error="{error}": on entering,
///   requests a plan from start to goal (a missing start or goal: FAILURE); RUNNING while it is
///   computed off the tick thread (a tick only polls); SUCCESS with the path written, or FAILURE
///   with the planner's message in `error`. Halting it abandons the plan. A replan to the same
///   goal is written only when it is shorter than what is left of the current path (measured
///   from the start's projection on it) or the current path is no longer free; otherwise the
///   current path stays (SUCCESS all the same), so the robot does not dither between ways round
///   an obstacle.
/// - FollowPath path="{path}" goal="{goal}" pose="{pose}" error="{error}": the PathFollower;
///   a new path (written by ComputePath while it drives) is taken up at once. RUNNING with the
///   command; SUCCESS when arrived (within the tolerances at the goal heading); FAILURE when the
///   bumper is pressed ("bumped"), the robot strayed ("strayed ... m from the path") or there is
///   no path, with the reason in `error`.
/// - BackUp backup_dist="0.15" backup_speed="0.1": GoBack's motion, `backup_dist` m backwards.
/// - Spin spin_dist="1.57" spin_speed="1.0": a turn in place through `spin_dist` rad.
///   (BackUp and Spin ignore the bumper, RUNNING then SUCCESS, like GoBack and Rotate.)
/// - GoalUpdated goal="{goal}": the first tick of a run (it was not ticked on the previous tick)
///   records the goal and returns FAILURE; later ticks return SUCCESS when the goal was written
///   since the previous tick, else FAILURE (Nav2's GoalUpdated).
/// - HasGoal goal="{goal}": SUCCESS while a goal is set.
/// - IsBumped: SUCCESS while the bumper is pressed.
/// - IsPathValid path="{path}" error="{error}": SUCCESS when the path is free in the known
///   world, else FAILURE with "the path is blocked".
/// - GoalSucceeded goal="{goal}": the goal is reached: clears it, outcome SUCCEEDED, SUCCESS.
/// - GoalAborted goal="{goal}" error="{error}": clears the goal, outcome ABORTED with the
///   error's text, FAILURE.
///
/// Then every registrar of `config.more_leaves`.
///
/// `context` and the planners must outlive the trees built.
void registerNavLeaves(bt::TreeFactory& factory, const NavLeafConfig& config, NavContext& context);

}  // namespace roomba_rrt::navigation
