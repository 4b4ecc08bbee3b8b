#include "roomba_rrt/sim/multi_robot_simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::sim {

namespace {

/// Overlap below this (m) is rounding of a push-back, not penetration (as for the furniture).
constexpr double kPenetrationTolerance = 1e-9;
/// Passes of walls-then-robots before a robot that still overlaps keeps its previous position.
constexpr int kMaxPlacePasses = 8;

const world::World& validated(const world::World& world) {
  validate(world);
  return world;
}

}  // namespace

MultiRobotSimulator::MultiRobotSimulator(const world::World& world)
    : world_(validated(world)),
      robots_(world_.robots.size()),
      coverage_(world_.robots.size(), CoverageGrid(world_)),
      grid_(world_.room.width, world_.room.height,
            2 * world::largestRadius(world_) + 2 * kContactTolerance,
            static_cast<int>(world_.robots.size())),
      max_radius_(world::largestRadius(world_)) {
  for (std::size_t i = 0; i < world_.robots.size(); ++i) {
    const robot::Pose2D& p = world_.robots[i].initial_pose;
    robots_[i].pose = p;
    grid_.insert(static_cast<int>(i), p.x - world_.room.origin.x, p.y - world_.room.origin.y);
  }
  reset();
}

bool MultiRobotSimulator::pushOutOfRobots(std::size_t robot, double& x, double& y) const {
  const double r = world_.robots[robot].radius;
  bool pushed = false;
  grid_.forEachNear(x - world_.room.origin.x, y - world_.room.origin.y, [&](int j) {
    if (static_cast<std::size_t>(j) == robot) return;
    const robot::Pose2D& q = robots_[j].pose;
    const double reach = r + world_.robots[j].radius;
    const double dx = x - q.x, dy = y - q.y;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= (reach - kPenetrationTolerance) * (reach - kPenetrationTolerance)) return;
    const double d = std::sqrt(d2);
    if (d > 0) {
      x = q.x + dx * (reach / d);
      y = q.y + dy * (reach / d);
    } else {
      x = q.x - reach;  // exactly on the other's centre: no normal, leave towards −x
    }
    pushed = true;
  });
  return pushed;
}

bool MultiRobotSimulator::overlapsRobot(std::size_t robot, double x, double y) const {
  const double r = world_.robots[robot].radius - kPenetrationTolerance;
  bool overlaps = false;
  grid_.forEachNear(x - world_.room.origin.x, y - world_.room.origin.y, [&](int j) {
    if (static_cast<std::size_t>(j) == robot) return;
    const double reach = r + world_.robots[j].radius;
    const double dx = x - robots_[j].pose.x, dy = y - robots_[j].pose.y;
    overlaps = overlaps || dx * dx + dy * dy < reach * reach;
  });
  return overlaps;
}

bool MultiRobotSimulator::place(std::size_t robot, double& x, double& y) const {
  const double r = world_.robots[robot].radius;
  if (robots_.size() == 1) return resolvePenetration(world_, r, x, y);  // Simulator, exactly
  for (int pass = 0; pass < kMaxPlacePasses; ++pass) {
    const bool clear_of_walls = resolvePenetration(world_, r, x, y);
    if (!pushOutOfRobots(robot, x, y)) return clear_of_walls;
  }
  return !penetrates(world_, r, x, y) && !overlapsRobot(robot, x, y);
}

void MultiRobotSimulator::senseContact() {
  const bool others = robots_.size() > 1;
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    Robot& robot = robots_[i];
    const double r = world_.robots[i].radius;
    resolvePenetration(world_, r, robot.pose.x, robot.pose.y);
    robot.bumper = senseBumper(world_, r, robot.pose);
    if (!others) continue;
    grid_.forEachNear(robot.pose.x - world_.room.origin.x, robot.pose.y - world_.room.origin.y,
                      [&](int j) {
                        if (static_cast<std::size_t>(j) == i) return;
                        const robot::Pose2D& q = robots_[j].pose;
                        const double reach = r + world_.robots[j].radius + kContactTolerance;
                        const double dx = q.x - robot.pose.x, dy = q.y - robot.pose.y;
                        if (dx * dx + dy * dy <= reach * reach)
                          pressBumper(robot.bumper, robot.pose, dx, dy);
                      });
  }
}

void MultiRobotSimulator::move(const std::vector<robot::Velocity>& commands) {
  if (commands.size() != robots_.size()) {
    throw std::invalid_argument("MultiRobotSimulator::move: " + std::to_string(commands.size()) +
                                " commands for " + std::to_string(robots_.size()) + " robots");
  }
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    Robot& robot = robots_[i];
    const world::RobotSpec& spec = world_.robots[i];
    robot.last_command =
        robot::clampCommand(commands[i], spec.max_linear_speed, spec.max_angular_speed);
    const robot::Pose2D previous = robot.pose;
    robot.pose = robot::integrateArc(robot.pose, robot.last_command, world_.step);
    // Push back onto whatever the step ran into; where the disc does not fit at all, stay put.
    if (!place(i, robot.pose.x, robot.pose.y)) {
      robot.pose.x = previous.x;
      robot.pose.y = previous.y;
    }
    if (robot.pose.x != previous.x || robot.pose.y != previous.y) {
      coverage_[i].markDisc(robot.pose.x, robot.pose.y, spec.radius);
      grid_.move(static_cast<int>(i), robot.pose.x - world_.room.origin.x,
                 robot.pose.y - world_.room.origin.y);
    }
  }
  ++steps_;
}

void MultiRobotSimulator::step(const std::vector<robot::Velocity>& commands) {
  senseContact();
  move(commands);
}

double MultiRobotSimulator::unionCoverage() const {
  if (coverage_.size() == 1) return coverage_[0].coverage();
  return unionCoverageGrid().coverage();
}

CoverageGrid MultiRobotSimulator::unionCoverageGrid() const {
  CoverageGrid all = coverage_[0];
  for (std::size_t i = 1; i < coverage_.size(); ++i) all.merge(coverage_[i]);
  return all;
}

void MultiRobotSimulator::setPose(std::size_t robot, const robot::Pose2D& pose) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
    throw util::InvalidInput("pose", "must be finite");
  }
  robot::Pose2D placed{pose.x, pose.y, robot::wrapAngle(pose.theta)};
  if (!place(robot, placed.x, placed.y)) {
    throw util::InvalidInput("pose", "the robot does not fit at the requested pose");
  }
  Robot& r = robots_[robot];
  r.pose = placed;
  grid_.move(static_cast<int>(robot), placed.x - world_.room.origin.x,
             placed.y - world_.room.origin.y);
  r.bumper = senseBumper(world_, world_.robots[robot].radius, r.pose);
  coverage_[robot].markDisc(r.pose.x, r.pose.y, world_.robots[robot].radius);
}

void MultiRobotSimulator::reset() {
  steps_ = 0;
  // Everyone off the floor first, so that a robot's initial pose never collides with another's
  // current one; the initial poses are clear of each other (validate()).
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    const robot::Pose2D& p = world_.robots[i].initial_pose;
    robots_[i].pose = p;
    grid_.move(static_cast<int>(i), p.x - world_.room.origin.x, p.y - world_.room.origin.y);
  }
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    coverage_[i].clear();
    robots_[i].last_command = {};
    setPose(i, world_.robots[i].initial_pose);
  }
}

std::vector<world::RobotSpec> spreadRobots(const world::World& world, int n) {
  if (n < 1 || static_cast<std::size_t>(n) > world::kMaxRobots) {
    throw std::invalid_argument("spreadRobots: the number of robots must be in [1, " +
                                std::to_string(world::kMaxRobots) + "], got " + std::to_string(n));
  }
  const double r = world.robot().radius;
  for (int cells = n; cells <= 64 * n; ++cells) {
    const int rows = std::max(
        1, static_cast<int>(std::lround(std::sqrt(cells * world.room.height / world.room.width))));
    const int columns = (cells + rows - 1) / rows;
    const double w = world.room.width / columns, h = world.room.height / rows;
    if (std::min(w, h) < 2 * r) break;  // neighbours would overlap
    std::vector<world::RobotSpec> robots;
    for (int row = 0; row < rows && static_cast<int>(robots.size()) < n; ++row) {
      for (int column = 0; column < columns && static_cast<int>(robots.size()) < n; ++column) {
        const double x = world.room.origin.x + (column + 0.5) * w;
        const double y = world.room.origin.y + (row + 0.5) * h;
        if (penetrates(world, r, x, y)) continue;
        robots.push_back(world::RobotSpec{"robot" + std::to_string(robots.size() + 1),
                                          robot::Pose2D{x, y, 0.0}, r,
                                          world.robot().max_linear_speed,
                                          world.robot().max_angular_speed, world.robot().sensors});
      }
    }
    if (static_cast<int>(robots.size()) == n) return robots;
  }
  throw std::invalid_argument("spreadRobots: " + std::to_string(n) +
                              " robots do not fit in the room");
}

void MultiRobotSimulator::setSpeedLimits(double max_linear_speed, double max_angular_speed) {
  world::World next = world_;
  for (world::RobotSpec& robot : next.robots) {
    robot.max_linear_speed = max_linear_speed;
    robot.max_angular_speed = max_angular_speed;
  }
  // The world's rule of v·step below every robot's radius, worded for the value that changed.
  for (const world::RobotSpec& spec : world_.robots) {
    const double fastest = spec.radius / world_.step;
    util::require(
        max_linear_speed < fastest, "max_linear_speed",
        "below " + util::show(fastest) + " m/s (" + (spec.name.empty() ? "the robot" : spec.name) +
            " would move its radius or more in one step of " + util::show(world_.step) + " s)",
        max_linear_speed);
  }
  validate(next);  // the world's rules: ranges, and v·step below every robot's radius
  world_ = next;
}

}  // namespace roomba_rrt::sim
