// Navigation as a behavior tree: goal in, (v, ω) out, from a tree file (config/roomba_nav_tree.xml,
// config/roomba_clean_nav_tree.xml). ROS-free: the roomba_bt node and roomba_nav_eval are thin
// adapters around it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/bt/tree.h"
#include "roomba_rrt/navigation/command_latency.h"
#include "roomba_rrt/navigation/nav_leaves.h"
#include "roomba_rrt/navigation/pose_predictor.h"

namespace roomba_rrt::navigation {

/// A tree of navigation leaves (nav_leaves.h) and the lab's leaves (roomba_tree.h), on a
/// blackboard with the keys the application writes: `goal` (Pose2D, unset: no goal) and `pose`
/// (Pose2D, every tick). The tree writes `path` and `error`.
///
/// Goals: setGoal() preempts the current one (the tree is halted, so the new goal is planned at
/// once, as Nav2's navigator does); cancelGoal() halts the tree and clears the goal. The outcome
/// is kActive until a GoalSucceeded / GoalAborted leaf ends the goal; a tree without them ends
/// it when the root finishes with a goal set (SUCCESS: succeeded, FAILURE: aborted with `error`).
class NavBt {
 public:
  /// The tree in `tree_file` (bt::TreeFileError naming the element and line when invalid;
  /// std::invalid_argument naming the field for bad parameters).
  NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& tree_file);
  /// The tree in `xml`; `source` names it in error messages.
  NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& xml,
        const std::string& source);
  // The leaves point into the context: neither copied nor moved.
  NavBt(const NavBt&) = delete;
  NavBt& operator=(const NavBt&) = delete;

  /// A new goal (util::InvalidInput naming the component when it is not finite).
  void setGoal(const robot::Pose2D& goal);
  void cancelGoal();

  /// FollowPath's new limits and tolerances, from its next tick (validated first:
  /// util::InvalidInput naming the field, and nothing changes). `params.rate` is ignored.
  void setFollowerParams(const FollowerParams& params);
  /// The lab's constants for the cleaning leaves of a tree that has them, from the next motion
  /// that starts (as RoombaBehavior::setParams). `params.rate` is ignored.
  void setRoombaParams(const behavior::RoombaParams& params);

  /// The times of the next tick, in the robot's clock (s): when it runs and the stamp of the pose
  /// it is given. Optional: without them the loop counts as on time. From them CommandLatency
  /// estimates how late the commands land, and the cleaning leaves slow down beyond
  /// LatencySpeedPolicy::kOnTimeTicks (speedScale()).
  void observeTiming(double now, double pose_stamp) { latency_.observe(now, pose_stamp); }
  /// The estimated latency of the loop (s; one tick without observeTiming()).
  double latency() const { return latency_.latency(); }
  /// The factor on the cleaning's speeds in force (1: on time).
  double speedScale() const { return context_.speed_scale; }

  /// One tick: the bumper and pose of this step in, the command out (zero when no leaf runs).
  /// The leaves see the pose driven forward over the config's pose_latency (PosePredictor).
  robot::Velocity tick(const robot::BumperState& bumper, const robot::Pose2D& pose);

  GoalOutcome outcome() const { return context_.outcome; }
  /// Why the last goal was aborted.
  const std::string& message() const { return context_.message; }
  /// The current plan (nullptr before the first).
  const Path* path() const { return board_->get<Path>("path"); }
  /// The active leaf's name (for ~state), "Idle" before any leaf ran.
  const std::string& stateName() const { return *context_.state_name; }
  /// Whether the robot is done and stands (~state then reads "Idle"): no goal is active, the
  /// tree's last tick did not return RUNNING and its command was zero. A tick that returns
  /// RUNNING with a zero command (a recovery just ended, the next try starts at the next tick;
  /// a follower holding still) is not idle: the tree has more to do.
  bool idle() const { return idle_; }
  /// The lab's motion the last command stands for (the cleaning and recovery leaves set it).
  behavior::RoombaState state() const { return context_.state; }
  bt::Tree& tree() { return tree_; }

 private:
  NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& text,
        const std::string& source, bool from_file);

  NavContext context_;
  behavior::RoombaParams params_;  ///< the cleaning leaves' constants (context_.params points here)
  std::shared_ptr<bt::Blackboard> board_;
  bt::Blackboard::Entry<robot::Pose2D>* goal_;
  bt::Blackboard::Entry<robot::Pose2D>* pose_;
  PosePredictor predictor_;
  CommandLatency latency_;
  bt::Tree tree_;
  bool idle_ = true;
};

/// The default planner options of navigation: RRT-Connect, exact segment checks, smoothed.
planning::PlannerOptions defaultNavPlannerOptions();

/// defaultNavPlannerOptions() for planning in `world`: exactly those in a room (bounds' diagonal
/// up to kRoomDiagonal); in a larger map steps of diagonal / 100 and 20 000 iterations per
/// 100 m² (at most 200 000), so a 50 m floor plans about as often as a room does.
planning::PlannerOptions navPlannerOptions(const planning::Problem& world);

/// Leaf configuration with the planning library in-process on `world` (a planning::Problem whose
/// start and goal are ignored): one InProcessPlanner in `mode` per ComputePath, and `world` as
/// the known world (util::InvalidInput naming the field when the planner refuses it).
NavLeafConfig inProcessNavConfig(
    const planning::Problem& world,
    const planning::PlannerOptions& options = defaultNavPlannerOptions(),
    InProcessPlanner::Mode mode = InProcessPlanner::Mode::kThread);

/// The <TreeNodesModel> (BehaviorTree.CPP v4, for Groot2) of every node a roomba_bt tree can
/// use: the lab's leaves, the navigation leaves, those of `more` (registrars that describe their
/// leaves without building any, e.g. coverage::coverageLeaves) and our control nodes, with their
/// ports.
std::string treeNodesModel(const std::vector<LeafRegistrar>& more = {});

/// Whether the tree file (or a file it includes) uses a navigation leaf (or one of `more`'s):
/// the factory that knows the lab's and the navigation leaves is asked which of its types the
/// file uses (bt::TreeFileError when the file cannot be read or parsed).
bool usesNavigationLeaves(const std::string& tree_file,
                          const std::vector<LeafRegistrar>& more = {});

/// Whether the tree file (or a file it includes) uses one of `more`'s leaves (with
/// coverage::coverageLeaves: whether it is a cleaning tree; bt::TreeFileError as above).
bool usesLeavesOf(const std::string& tree_file, const std::vector<LeafRegistrar>& more);

}  // namespace roomba_rrt::navigation
