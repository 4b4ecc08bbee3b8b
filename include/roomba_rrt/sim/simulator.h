// The simulated Roomba: a disc on a unicycle base in a room with furniture, with a bumper and a
// coverage grid. ROS-free; the roomba_sim node and the in-process coverage tool both drive it.
#pragma once

#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sim/coverage_grid.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sim {

/// One lab step is
///
///     BumperState b = sim.senseContact();   // 1. resolve contact, 2. recompute the bumper
///     Velocity cmd = behaviour.tick(b);     // 3. the behaviour decides
///     sim.move(cmd);                        // 4. clamp, integrate one step, mark coverage
///
/// Contact follows the lab: a disc that would end a step inside a wall or a piece of furniture is
/// pushed back onto it along the surface normal, without bounce and without changing the heading,
/// so after every move() the disc touches but never penetrates. The bumper counts touching as
/// pressed, so it stays pressed while the robot pushes on and clears on the first step after it
/// backs off.
class Simulator {
 public:
  /// Validates the world (std::invalid_argument naming the bad parameter) and places the robot at
  /// its initial pose, with that disc already counted as swept.
  explicit Simulator(const world::World& world);

  /// Steps 1–2: pushes the disc out of anything it penetrates (nothing to do after move(); needed
  /// after setPose()) and recomputes the bumper from the geometry.
  robot::BumperState senseContact();

  /// Step 4: clamps `cmd` to the world's speed limits (a NaN or infinite component counts as 0),
  /// integrates the exact unicycle arc over one step, resolves contact and marks coverage.
  void move(const robot::Velocity& cmd);

  /// senseContact() followed by move(cmd): one step with a command fixed in advance (the node,
  /// which applies the latest /cmd_vel).
  robot::BumperState step(const robot::Velocity& cmd);

  const robot::Pose2D& pose() const { return pose_; }
  const robot::BumperState& bumper() const { return bumper_; }
  /// The clamped command applied by the last move() (zero before the first).
  robot::Velocity lastCommand() const { return last_command_; }
  /// Simulated time: number of move() calls since construction or reset(), times world().step.
  double time() const { return steps_ * world_.step; }
  long steps() const { return steps_; }

  double coverage() const { return coverage_.coverage(); }
  const CoverageGrid& coverageGrid() const { return coverage_; }
  const world::World& world() const { return world_; }

  /// Puts the robot at `pose` (pushed out of anything it penetrates) and marks that disc swept.
  /// θ is wrapped to (−π, π]. A non-finite pose is rejected with util::InvalidInput.
  void setPose(const robot::Pose2D& pose);
  /// Back to the initial pose, time 0, coverage cleared, bumper released, command zero.
  void reset();

 private:
  world::World world_;
  CoverageGrid coverage_;
  robot::Pose2D pose_;
  robot::BumperState bumper_;
  robot::Velocity last_command_;
  long steps_ = 0;
};

}  // namespace roomba_rrt::sim
