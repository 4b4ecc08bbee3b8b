// Cleaning a home with a map of it that may be stale (issue 43): roomba_coverage --unknown
// --known-map in one process, roomba_bt ~unknown ~known_map over ROS. ROS-free: scans, bumper and
// pose in, velocity out.
//
// The robot is given a map (known_map.h: say, the apartment without the furniture that came
// since) and has its lidar and bumper:
//   1. it plans the cleaning's rows at once, on the map as BuiltMap makes it from the known map
//      and the first scan (the known walls are walls; the known floor is floor unless seen
//      otherwise), and drives them with the cleaning tree (config/roomba_coverage_tree.xml), as
//      on a map it knows;
//   2. after every scan it looks at the next kCheckAhead of the plan on the map as it is now:
//      when a cell that was floor when the plan was made is blocked now within kGuardMargin of
//      the robot's disc along it (furniture the map lacks, seen by the lidar; a bump's cell),
//      the rows left are made free on that map
//      (CoveragePlanner::repair: each row cut round what stands in it, new transits, the order
//      kept) and a new tree drives them from where the robot is; the floor swept so far goes
//      with it, for the touch-up, which then sweeps what the cut rows left;
//   3. a bump is marked in the map, the tree backs off and resumes; the next look sees the rest
//      blocked by the bumped cell and plans again round it.
// A plan is never made through a cell seen occupied: every plan is made on the map of that
// moment, whose seen cells are occupied for good (BuiltMap). Nothing is explored first: floor
// beyond the known map is cleaned as the lidar shows it clearly free, when a plan is made.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/coverage/coverage_planner.h"
#include "roomba_rrt/exploration/built_map.h"
#include "roomba_rrt/exploration/known_map.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

class CleanKnownMap {
 public:
  /// For `robot` starting at its initial_pose with the map `known` (checkKnownMap: throws
  /// util::InvalidInput naming the map's field when it does not fit); cells of
  /// `coverage_cell_size` for the plans; `pose_latency` as NavLeafConfig's; the cleaning tree in
  /// `tree_file`.
  CleanKnownMap(const world::RobotSpec& robot, const KnownMap& known, double coverage_cell_size,
                const behavior::RoombaParams& params, std::uint32_t seed, double pose_latency,
                std::string tree_file);
  ~CleanKnownMap();

  /// A scan taken from `sensor` (the sensor's pose in the map): into the map. "" or why it was
  /// refused (mapping::checkScan), naming the field.
  std::string addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan);

  /// One tick at simulated `time`: the bumper goes into the map, the plan is looked at (after a
  /// new scan) and made free again when blocked, then the cleaning tree decides the command from
  /// `bumper` and `pose` (the robot's pose at `pose_stamp`: NavBt::observeTiming).
  robot::Velocity tick(double time, const robot::BumperState& bumper, const robot::Pose2D& pose,
                       double pose_stamp);

  const std::string& stateName() const;
  behavior::RoombaState state() const;
  /// The cleaning tree driving now (null before the first scan).
  navigation::NavBt* activeTree() { return clean_.get(); }
  /// The cleaning tree is done: the robot stands for good.
  bool done() const { return clean_ && clean_->idle(); }
  /// The lab's constants for the tree driving and those made from now on.
  void setParams(const behavior::RoombaParams& params);
  /// Plans made so far: 1 + the times the rest was blocked.
  int plans() const { return plans_; }
  const BuiltMap& map() const { return map_; }
  const mapping::OccupancyMapper& mapper() const { return map_.mapper(); }

  /// m of the rest of the plan looked at, from where the robot is: what lies beyond is made free
  /// when the robot comes near it, once the lidar has seen it from closer (the furnished room
  /// planned 44 times looking at all of it, 12 times looking 3 m ahead, as fast to 95 %).
  static constexpr double kCheckAhead = 3.0;
  /// m between two points of the rest of the plan where the robot's disc is looked at.
  static constexpr double kCheckStep = 0.02;
  /// m round the robot where the rest of the plan is not looked at when the robot's own disc is
  /// not free: it stands there already (touching what it bumped into, or what it saw late
  /// beside it).
  static constexpr double kAroundRobot = 0.1;
  /// m beyond the robot's disc along the plan where a cell that became blocked makes a new tree:
  /// its motion guard then knows it too (the tree's guard keeps the robot off what was known when
  /// it was made). A row planned 1 cm from a desk whose top the first scan had not seen, driven
  /// 2.5 cm off after a turn in place, touched the desk's corner with a guard that did not know
  /// it.
  static constexpr double kGuardMargin = 0.05;
  /// m the robot moves before where it stands is remembered as floor again.
  static constexpr double kFootprintSpacing = 0.1;

 private:
  /// Whether a cell of `grid` within kGuardMargin of the robot's disc along the next
  /// kCheckAhead of the tree's plan is blocked now and was floor when the tree was made.
  bool restChanged(const geometry::OccupancyGrid& grid, const robot::Pose2D& pose);
  /// A new tree on the map as it is now, going on with the floor swept so far.
  void plan(std::shared_ptr<const geometry::OccupancyGrid> grid, const robot::Pose2D& pose);

  world::RobotSpec robot_;
  double coverage_cell_size_;
  behavior::RoombaParams params_;
  std::uint32_t seed_;
  double pose_latency_;
  std::string tree_file_;
  BuiltMap map_;
  geometry::Point2 last_footprint_;

  std::shared_ptr<const coverage::CoveragePlanner> planner_;  ///< the tree's
  std::shared_ptr<const geometry::OccupancyGrid> planned_;    ///< the map the tree's world is
  std::unique_ptr<navigation::NavBt> clean_;
  std::size_t checked_scans_ = 0;  ///< the mapper's scans when the plan was last looked at
  int plans_ = 0;
  robot::Velocity stop_;
};

}  // namespace roomba_rrt::exploration
