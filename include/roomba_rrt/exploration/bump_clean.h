// Cleaning a home the robot has never seen with nothing but its bumper, its IR light bumper and
// its odometry: the classic Roomba, no lidar (issue 43). roomba_coverage --unknown in process and
// roomba_bt ~unknown over ROS use it for a robot whose sensors reach no farther than kLongRange
// (cleansByTouch); a robot with a lidar maps and explores instead (explore_clean.h). ROS-free:
// IR scans, bumper and pose in, velocity out.
//
// The robot
//   - maps what it touches and sees at arm's length (swept_map.h): the floor under its disc as
//     it goes, each IR return and each bump as a point on an obstacle;
//   - drives the moves online_boustrophedon.h chooses: rows and shifts straight along the map's
//     axes, braking to stop short of every point found ahead (the IR light bumper sees 0.15 m
//     beyond the bumper, enough to stop from 0.5 m/s), transits along a path over floor it has
//     swept (navigation::PathFollower);
//   - on a bump marks the point, backs off a few centimetres, and chooses again;
//   - is done, standing still, when no move is left.
// It never plans through a centre near a point it has found on an obstacle; a row into floor it
// has not seen may still bump into what its six beams did not catch (a chair leg between two
// beams, an edge beside its path): those bumps are what this robot pays for having no lidar.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "roomba_rrt/behavior/roomba_params.h"
#include "roomba_rrt/behavior/roomba_state.h"
#include "roomba_rrt/exploration/online_boustrophedon.h"
#include "roomba_rrt/exploration/swept_map.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/navigation/path_follower.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

/// m: a range sensor that reaches this far lets the robot see a frontier from where it may stand
/// (ExploreClean::kViewDistance), so it explores with it; one that does not (the IR light bumper,
/// 0.15 m) only tells it what it is about to touch.
constexpr double kLongRange = 1.0;

/// Whether `robot` cleans a home it has never seen by touch (BumpClean): none of its sensors
/// reaches kLongRange, or it has none (bumper only).
bool cleansByTouch(const world::RobotSpec& robot);

/// How BumpClean drives; like the cleaning tree's driving (coverage_leaves.cpp: a robot vacuum,
/// not a cautious navigator).
struct BumpCleanOptions {
  double clearance = 0.01;     ///< m kept from every point found on an obstacle
  double transit_speed = 1.0;  ///< m/s between moves, over swept floor
  double turn_speed = 2.0;     ///< rad/s: the Roomba's limit
  double accel = 2.0;          ///< m/s²: starting, and braking before a point found ahead
  double backup = 0.03;        ///< m backed off after a bump
  double backup_speed = 0.15;  ///< m/s
  double move_timeout = 30.0;  ///< s a move (its transit, turn and drive) may take
  BoustrophedonOptions plan;
};

class BumpClean {
 public:
  /// For `robot` (its radius, sensors and initial_pose); rows at `params.forward_speed`, ticks at
  /// `params.rate`.
  BumpClean(const world::RobotSpec& robot, const behavior::RoombaParams& params,
            const BumpCleanOptions& options = {});

  /// A scan taken from `sensor` (the sensor's pose in the map): each return (a range in
  /// [range_min, range_max]) is a point on an obstacle. "" or why it was refused
  /// (mapping::checkScan), naming the field.
  std::string addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan);

  /// One tick: the disc's floor swept, a bump into the map, then the command for this tick.
  robot::Velocity tick(double time, const robot::BumperState& bumper, const robot::Pose2D& pose);

  /// No move is left: the robot stands for good.
  bool done() const { return phase_ == Phase::kDone; }
  /// "Row", "Shift", "Transit", "Turn", "BackUp" or "Done".
  const std::string& stateName() const;
  /// For pictures: rows and shifts MoveForward, transits MoveInSpiral, backing off GoBack,
  /// turning and done Rotate.
  behavior::RoombaState state() const;
  const SweptMap& map() const { return map_; }
  const OnlineBoustrophedon& planner() const { return planner_; }
  int moves() const { return moves_; }  ///< moves planned so far
  /// The move being driven (none before the first tick and once done).
  const std::optional<Move>& move() const { return move_; }
  /// Simulated s when it was done; negative while cleaning.
  double doneAt() const { return done_at_; }

 private:
  enum class Phase { kTransit, kTurn, kDrive, kBackUp, kDone };
  /// The next move from `pose` (or done): its transit, or its turn.
  void plan(double time, const robot::Pose2D& pose);
  robot::Velocity turn(double time, const robot::Pose2D& pose);
  robot::Velocity drive(double time, const robot::Pose2D& pose);
  /// `v` within the acceleration limit from the last command.
  double ramp(double v) const;
  void markBump(const robot::Pose2D& pose, const robot::BumperState& bumper);

  world::RobotSpec robot_;
  behavior::RoombaParams params_;
  BumpCleanOptions options_;
  SweptMap map_;
  OnlineBoustrophedon planner_;
  navigation::PathFollower follower_;
  navigation::Path path_;  ///< the transit being followed (the follower keeps a pointer to it)

  Phase phase_ = Phase::kTurn;
  std::optional<Move> move_;
  double move_since_ = 0;
  geometry::Point2 backup_from_;
  bool was_pressed_ = false;
  bool started_ = false;
  robot::Velocity last_;
  int moves_ = 0;
  long swept_before_ = 0;  ///< the map's swept cells when the move began
  double done_at_ = -1;
};

}  // namespace roomba_rrt::exploration
