// Cleaning a home the robot has never seen: roomba_coverage --unknown in one process, roomba_bt
// ~unknown over ROS. ROS-free: scans, bumper and pose in, velocity out.
//
// The robot starts with an empty map and a range sensor:
//   1. mapping: every scan (addScan) and every bump goes into a log-odds map
//      (mapping::OccupancyMapper), as roomba_mapper builds /map over ROS, and into one of
//      cells eight times smaller for the cleaning (BuiltMap::fineGrid);
//   2. exploring: it drives to the nearest frontier it can reach (exploration::nearestFrontier:
//      unknown cells are walls until seen) with the navigation tree (config/roomba_nav_tree.xml)
//      planning on the map as built so far, at the cleaning's transit speed and without turning
//      at the goal (the lidar sees all round); it looks again every kReplanPeriod and turns to a
//      nearer frontier when one appears; a frontier it arrived at but still sees, or could not
//      reach, is given up (with every frontier cell it could see from there);
//   3. cleaning: once no frontier it can reach is left, the cleaning tree (config/roomba_coverage_
//      tree.xml) plans its rows on the fine map it built (unknown and occupied cells as walls) and
//      drives them, as on a known map;
//   4. touching up: once that tree has driven its rows and the first of its touch-up passes
//      (kCleanTouchUps), the touch-up tree (config/roomba_touch_up_tree.xml) goes back for the
//      spots the map as it is by then shows missed (the robot saw the floor beside walls and
//      furniture better from the rows than from where it explored), from every pose the robot
//      was at.
// Exploring first and cleaning after keeps the cleaning's plan whole (rows across each room, no
// row cut where the map ended when it was planned); the lidar sees a room from its doorway, so
// exploring is short beside cleaning (the benchmark rows measure both).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/exploration/built_map.h"
#include "roomba_rrt/exploration/frontiers.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

/// The cleaning tree's configuration in `world` (a known one, or the one the robot built): its
/// coverage leaves plan with `planner`, its navigation leaves in process.
navigation::NavLeafConfig cleaningConfig(const world::World& world,
                                         const behavior::RoombaParams& params,
                                         std::shared_ptr<const coverage::CoveragePlanner> planner);

/// The two trees, by file (config/roomba_nav_tree.xml and config/roomba_coverage_tree.xml).
struct ExploreCleanTrees {
  std::string explore;  ///< drives to a frontier (navigation leaves)
  std::string clean;    ///< cleans the built map (coverage leaves)
  /// Goes back for the spots missed on the map as it is once the cleaning is done (coverage
  /// leaves without PlanCoverage: config/roomba_touch_up_tree.xml); "": no such round.
  std::string touch_up;
};

class ExploreClean {
 public:
  /// For `robot` starting at its initial_pose; cells of `coverage_cell_size` for the cleaning's
  /// plan; `pose_latency` as NavLeafConfig's.
  ExploreClean(const world::RobotSpec& robot, double coverage_cell_size,
               const behavior::RoombaParams& params, std::uint32_t seed, double pose_latency,
               ExploreCleanTrees trees);
  ~ExploreClean();

  /// A scan taken from `sensor` (the sensor's pose in the map): into the map. "" or why it was
  /// refused (mapping::checkScan), naming the field.
  std::string addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan);

  /// One tick at simulated `time`: the bumper goes into the map, then the phase's tree decides
  /// the command from `bumper` and `pose` (the robot's pose at `pose_stamp`:
  /// NavBt::observeTiming).
  robot::Velocity tick(double time, const robot::BumperState& bumper, const robot::Pose2D& pose,
                       double pose_stamp);

  const std::string& stateName() const;
  behavior::RoombaState state() const;
  bool cleaning() const { return clean_ != nullptr; }
  /// The tree driving now (to a frontier, or cleaning); null while the robot stands and looks.
  navigation::NavBt* activeTree() { return clean_ ? clean_.get() : explore_.get(); }
  /// Cleaning, the cleaning tree is done and so are the touch-up rounds: the robot stands for
  /// good.
  bool done() const {
    return clean_ && clean_->idle() && (rounds_ >= kTouchUpRounds || trees_.touch_up.empty());
  }
  /// The lab's constants for the trees made from now on and the one driving.
  void setParams(const behavior::RoombaParams& params);
  /// Simulated s when exploring ended (the cleaning began); negative while exploring.
  double exploredAt() const { return explored_at_; }
  const mapping::OccupancyMapper& mapper() const { return map_.mapper(); }

  static constexpr double kReplanPeriod = 1.0;  ///< s between two looks for a nearer frontier
  /// m: a frontier is in view this far over free floor (FrontierOptions::view_distance).
  static constexpr double kViewDistance = 1.0;
  /// m beyond the robot's radius its goals keep from what is not clearly free (the planner's
  /// margin and then some: a goal it cannot plan to is a goal given up).
  static constexpr double kGoalMargin = 0.03;
  /// m beyond the view distance round a given-up goal where frontier cells are given up with it
  /// (every cell it could see from there: each give-up takes at least one cell away).
  static constexpr double kGiveUpMargin = 0.05;
  static constexpr double kGoalTimeout = 60.0;  ///< s to reach a frontier before giving it up
  static constexpr double kSameGoal = 0.3;      ///< m: a goal this close to the current is kept
  /// m/s on the way to a frontier (the cleaning tree's transit_speed; at most the robot's
  /// max_linear_speed): the follower's default 0.3 m/s made exploring a third of the cleaning.
  static constexpr double kExploreSpeed = 1.0;
  /// s the robot stands and looks with no frontier in reach before it starts cleaning.
  static constexpr double kConfirmDone = 1.0;
  /// The cleaning plans on the map in cells this many times smaller than the exploring's
  /// (BuiltMap::fineGrid: 0.625 cm), so that its rows reach as close to the walls as on a known
  /// map: a return blocks the whole fine cell it ends in, and at 1.25 cm that kept the robot up
  /// to 1.25 cm further from the round chairs and the table than on a known map (the dining
  /// room's touch-ups reached 98.9 % where the known map's reach 99.2 %).
  static constexpr int kFineSplit = 8;
  /// Touch-up passes of the cleaning tree (on the map of the end of exploring) driven before the
  /// touch-up round replaces it: its second pass went for the 40 cm² spots of a map that has
  /// grown since (the willow crop: 81 s for 0.3 %), which the round on the map as it is then
  /// goes for as well.
  static constexpr int kCleanTouchUps = 1;
  /// Touch-up rounds on the map as it is once the cleaning (and the previous round) is done: the
  /// plan was made on the map of the end of exploring, and the robot saw the floor beside the
  /// walls and furniture better as it drove the rows (trees_.touch_up).
  static constexpr int kTouchUpRounds = 1;
  /// m the robot moves between two of the poses it remembers (swept_at_).
  static constexpr double kSweptStep = 0.01;
  /// The touch-up round plans on a lattice this many times finer than the cleaning's: the
  /// cleaning's 2.5 cm lattice counts as floor only the squares whose centre is free, and
  /// where a wall lies anywhere in them it leaves up to 2.5 cm along it for no row to reach.
  static constexpr double kTouchUpSplit = 2;

 private:
  /// The cleaning tree (not yet a touch-up round) has driven its rows and kCleanTouchUps passes.
  bool cleaningTouchedUp() const;
  /// Looks for the nearest frontier from `pose` and drives there (`arrived`: the previous goal
  /// was reached); starts cleaning when none is left.
  void nextGoal(double time, const robot::Pose2D& pose, bool arrived);
  /// `frontiers` (of `grid`) without their cells round given-up goals, and without those that
  /// keep fewer than min_cells.
  std::vector<exploration::Frontier> openFrontiers(std::vector<exploration::Frontier> frontiers,
                                                   const geometry::OccupancyGrid& grid) const;
  /// `grid` as a world (unknown and occupied cells as walls) with the robot at `pose`.
  world::World builtWorld(std::shared_ptr<const geometry::OccupancyGrid> grid,
                          const robot::Pose2D& pose) const;
  void startCleaning(double time, const robot::Pose2D& pose);
  /// A touch-up round (trees_.touch_up) on the map as it is, from the floor swept so far.
  void startTouchUp(const robot::Pose2D& pose);
  /// The cleaning tree's configuration on the fine grid of the map as it is, the robot at `pose`,
  /// on a lattice of `cell_size`; its planner in `planner`.
  navigation::NavLeafConfig cleaningOnMap(
      const robot::Pose2D& pose, double cell_size,
      std::shared_ptr<const coverage::CoveragePlanner>& planner);

  world::RobotSpec robot_;
  double coverage_cell_size_;
  behavior::RoombaParams params_;
  std::uint32_t seed_;
  double pose_latency_;
  BuiltMap map_;  ///< scans, bumps and where the robot stood
  exploration::FrontierOptions frontier_options_;

  std::unique_ptr<navigation::NavBt> explore_;  ///< driving to the current frontier goal
  geometry::Point2 goal_;
  double goal_since_ = 0, last_look_ = -1e9;
  double none_since_ = -1;  ///< s since no frontier was in reach; negative: one is
  std::vector<geometry::Point2> given_up_;

  ExploreCleanTrees trees_;
  std::unique_ptr<navigation::NavBt> clean_;
  double explored_at_ = -1;
  int rounds_ = 0;  ///< touch-up rounds started
  /// Where the robot's centre was, every kSweptStep: the floor it swept, for the touch-ups.
  std::vector<geometry::Point2> swept_at_;
  robot::Velocity stop_;
};

}  // namespace roomba_rrt::exploration
