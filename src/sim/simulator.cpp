#include "roomba_rrt/sim/simulator.h"

#include <cmath>
#include <stdexcept>

#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/sim/contact.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::sim {

namespace {
const world::World& validated(const world::World& world) {
  validate(world);
  return world;
}
}  // namespace

Simulator::Simulator(const world::World& world) : world_(validated(world)), coverage_(world_) {
  reset();
}

robot::BumperState Simulator::senseContact() {
  resolvePenetration(world_, pose_.x, pose_.y);
  bumper_ = senseBumper(world_, pose_);
  return bumper_;
}

void Simulator::move(const robot::Velocity& cmd) {
  last_command_ =
      robot::clampCommand(cmd, world_.robot().max_linear_speed, world_.robot().max_angular_speed);
  const robot::Pose2D previous = pose_;
  pose_ = robot::integrateArc(pose_, last_command_, world_.step);
  // Push back onto whatever the step ran into; where the disc does not fit at all, stay put.
  if (!resolvePenetration(world_, pose_.x, pose_.y)) {
    pose_.x = previous.x;
    pose_.y = previous.y;
  }
  if (pose_.x != previous.x || pose_.y != previous.y) {
    coverage_.markDisc(pose_.x, pose_.y, world_.robot().radius);
  }
  ++steps_;
}

robot::BumperState Simulator::step(const robot::Velocity& cmd) {
  const robot::BumperState bumper = senseContact();
  move(cmd);
  return bumper;
}

void Simulator::setPose(const robot::Pose2D& pose) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
    throw util::InvalidInput("pose", "must be finite");
  }
  robot::Pose2D placed{pose.x, pose.y, robot::wrapAngle(pose.theta)};
  if (!resolvePenetration(world_, placed.x, placed.y)) {
    throw util::InvalidInput("pose", "the robot does not fit at the requested pose");
  }
  pose_ = placed;
  bumper_ = senseBumper(world_, pose_);
  coverage_.markDisc(pose_.x, pose_.y, world_.robot().radius);
}

void Simulator::reset() {
  coverage_.clear();
  last_command_ = {};
  steps_ = 0;
  setPose(world_.robot().initial_pose);
}

}  // namespace roomba_rrt::sim
