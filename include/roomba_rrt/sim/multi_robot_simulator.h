// Several simulated Roombas in one room: each a disc on a unicycle base with its own bumper and
// coverage, and discs to each other. ROS-free; roomba_sim and roomba_coverage drive it.
#pragma once

#include <cstddef>
#include <vector>

#include "roomba_rrt/robot/robot_state.h"
#include "roomba_rrt/sim/coverage_grid.h"
#include "roomba_rrt/sim/robot_grid.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sim {

/// The robots of world.robots, stepped together. One step is the lab's, for all of them:
///
///     sim.senseContact();                       // 1–2. every robot's bumper
///     commands[i] = behaviour[i].tick(sim.bumper(i));   // 3. each behaviour decides
///     sim.move(commands);                       // 4. every robot moves
///
/// Robots move one after the other in index order. Each is pushed back out of walls and furniture
/// as in Simulator (the lab's rule) and out of every other robot's disc along the line between the
/// centres, the other robot being an obstacle like the furniture: robots never push each other and
/// never overlap (a robot that cannot be placed keeps its previous position, which was clear). The
/// bumper counts a touching robot like a touching wall, on the side it touches. Robot–robot
/// contact looks only at the robots in the neighbouring cells of a RobotGrid.
///
/// With one robot (an unnamed one, today's world files) every pose, bumper and coverage cell is
/// bit for bit that of Simulator.
class MultiRobotSimulator {
 public:
  /// Validates the world (std::invalid_argument naming the bad parameter) and places every robot
  /// at its initial pose, with its disc already counted as swept.
  explicit MultiRobotSimulator(const world::World& world);

  std::size_t size() const { return world_.robots.size(); }
  const world::RobotSpec& spec(std::size_t robot) const { return world_.robots[robot]; }

  /// Steps 1–2 for every robot: pushes its disc out of the walls and furniture it penetrates
  /// (nothing to do after move()) and recomputes its bumper from walls, furniture and robots.
  void senseContact();
  /// Step 4: moves robot i by commands[i] (clamped to its limits), in index order. Throws
  /// std::invalid_argument unless there is one command per robot.
  void move(const std::vector<robot::Velocity>& commands);
  /// senseContact() followed by move(commands).
  void step(const std::vector<robot::Velocity>& commands);

  const robot::Pose2D& pose(std::size_t robot) const { return robots_[robot].pose; }
  const robot::BumperState& bumper(std::size_t robot) const { return robots_[robot].bumper; }
  robot::Velocity lastCommand(std::size_t robot) const { return robots_[robot].last_command; }
  double time() const { return steps_ * world_.step; }
  long steps() const { return steps_; }

  /// Fraction of the free floor swept by one robot, and by all of them together.
  double coverage(std::size_t robot) const { return coverage_[robot].coverage(); }
  const CoverageGrid& coverageGrid(std::size_t robot) const { return coverage_[robot]; }
  double unionCoverage() const;
  /// The union of every robot's swept cells (computed on request: stepping stays per robot).
  CoverageGrid unionCoverageGrid() const;
  const world::World& world() const { return world_; }

  /// Puts robot i at `pose`, pushed out of walls, furniture and other robots, and marks that disc
  /// swept. util::InvalidInput for a non-finite pose or one where the disc does not fit.
  void setPose(std::size_t robot, const robot::Pose2D& pose);
  /// Every robot back to its initial pose, time 0, coverage cleared, commands zero.
  void reset();
  /// Every robot's speed limits from now on (dynamic_reconfigure). util::InvalidInput naming the
  /// field, and nothing changes, when a limit is outside World's range or lets some robot move
  /// its radius or more in one step.
  void setSpeedLimits(double max_linear_speed, double max_angular_speed);

 private:
  struct Robot {
    robot::Pose2D pose;
    robot::BumperState bumper;
    robot::Velocity last_command;
  };

  /// Pushes robot i's disc at (x, y) out of walls, furniture and the other robots until nothing
  /// overlaps; false when that fails (the disc does not fit there).
  bool place(std::size_t robot, double& x, double& y) const;
  /// One pass over the robots near (x, y); true when robot i's disc was pushed.
  bool pushOutOfRobots(std::size_t robot, double& x, double& y) const;
  bool overlapsRobot(std::size_t robot, double x, double y) const;

  world::World world_;
  std::vector<Robot> robots_;
  std::vector<CoverageGrid> coverage_;
  RobotGrid grid_;
  double max_radius_ = 0;
  long steps_ = 0;
};

/// n robots named robot1 … robotn spread evenly over the room, facing +x, with the world's shared
/// radius, limits and sensors: the room is cut into rows × columns equal cells (about square) and
/// the robots stand at the centres of the free ones, row by row from the bottom; cells whose centre
/// puts the disc into furniture are skipped, taking more and smaller cells. One robot stands at the
/// room's centre, as in the lab. std::invalid_argument when n robots do not fit.
std::vector<world::RobotSpec> spreadRobots(const world::World& world, int n);

}  // namespace roomba_rrt::sim
