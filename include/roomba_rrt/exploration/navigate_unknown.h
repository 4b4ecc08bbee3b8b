// Driving to a goal in a home the robot has never seen (issue 43, item 4): the navigation tree
// (config/roomba_nav_tree.xml) plans on the map the robot builds from its scans, unknown cells
// taken as floor until seen, and plans again when the scans show an obstacle on the way.
// ROS-free: scans, bumper and pose in, velocity out.
//
// Every kLookPeriod the map is looked at again (BuiltMap::grid with Unknown::kFree, grown to
// take in the goal): when the rest of the path the tree follows is no longer free for the
// robot's disc in it, a new tree plans on it from where the robot is. A goal the tree gives up
// on (no way to the goal through what is known to be free or unknown, a goal now seen inside an
// obstacle) is planned again on the map as it is then, kRetries times, and then ends aborted
// with the tree's message. Given a map of the home (known_map.h), the robot starts from it: its
// walls stay walls, so the plans go through its doorways (issue 43's stale map).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/exploration/built_map.h"
#include "roomba_rrt/exploration/known_map.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

class NavigateUnknown {
 public:
  /// For `robot` (its radius and sensors) starting at its initial_pose, with the navigation tree
  /// in `tree_file`; `pose_latency` as NavLeafConfig's. With `known` (a map of the home that may
  /// be stale: known_map.h, checked with checkKnownMap, which throws util::InvalidInput naming
  /// its field), the map starts from it: its walls are walls for good, and the way to a goal
  /// goes through its doorways rather than through walls the robot has not seen yet.
  NavigateUnknown(const world::RobotSpec& robot, const behavior::RoombaParams& params,
                  std::uint32_t seed, double pose_latency, std::string tree_file,
                  const KnownMap* known = nullptr);
  ~NavigateUnknown();

  /// A scan taken from `sensor` (the sensor's pose in the map): into the map. "" or why it was
  /// refused (mapping::checkScan), naming the field.
  std::string addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan);

  /// A new goal, preempting the current one (util::InvalidInput naming the field: "goal.x" when
  /// not finite, "goal" when farther than kMaxGoalDistance from the robot's map).
  void setGoal(const robot::Pose2D& goal);
  void cancelGoal();
  /// FollowPath's limits and tolerances for the tree driving and those made from now on
  /// (validated first: util::InvalidInput naming the field, and nothing changes). `params.rate`
  /// is ignored.
  void setFollowerParams(const navigation::FollowerParams& params);

  /// One tick at simulated `time`: the bumper goes into the map, then the tree decides the
  /// command from `bumper` and `pose` (the robot's pose at `pose_stamp`: NavBt::observeTiming).
  robot::Velocity tick(double time, const robot::BumperState& bumper, const robot::Pose2D& pose,
                       double pose_stamp);

  navigation::GoalOutcome outcome() const { return outcome_; }
  /// Why the last goal was aborted.
  const std::string& message() const { return message_; }
  const std::string& stateName() const;
  /// The tree driving to the goal now (null before the first scan and between goals).
  navigation::NavBt* tree() { return nav_.get(); }
  /// How many trees planned the current goal (1 + the times its path was blocked).
  int plans() const { return plans_; }
  const BuiltMap& map() const { return map_; }

  static constexpr double kLookPeriod = 0.5;  ///< s between two looks at the path in the map
  /// m: a goal farther than this from the map's extent is refused (the map grown to take it in
  /// is the planner's world: 30 m on each side is 1.4 M cells).
  static constexpr double kMaxGoalDistance = 30.0;
  /// m: a goal the built map puts in an obstacle's grown cells is moved to the nearest free
  /// point this near (freePointNear's tolerance); arriving there (within the follower's
  /// xy_tolerance) succeeds.
  static constexpr double kGoalShift = 0.1;
  /// Times a goal whose tree gave up is planned again on the map as it is then.
  static constexpr int kRetries = 2;
  /// m the robot moves before where it stands is remembered as floor again.
  static constexpr double kFootprintSpacing = 0.1;

 private:
  /// The map now, grown to take in the goal: a new tree when the path is no longer free in it.
  void look(double time, const robot::Pose2D& pose);
  void end(navigation::GoalOutcome outcome, std::string message);

  world::RobotSpec robot_;
  behavior::RoombaParams params_;
  navigation::FollowerParams follower_;
  std::uint32_t seed_;
  double pose_latency_;
  std::string tree_file_;
  BuiltMap map_;
  geometry::Point2 last_footprint_;

  robot::Pose2D goal_;
  navigation::GoalOutcome outcome_ = navigation::GoalOutcome::kNone;
  std::string message_;
  std::unique_ptr<navigation::NavBt> nav_;
  double last_look_ = -1e9;
  int plans_ = 0;
  int retries_ = 0;  ///< of the current goal
  robot::Velocity stop_;
};

}  // namespace roomba_rrt::exploration
