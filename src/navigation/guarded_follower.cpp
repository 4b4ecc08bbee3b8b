#include "roomba_rrt/navigation/guarded_follower.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "roomba_rrt/robot/unicycle.h"

namespace roomba_rrt::navigation {

GuardedFollower::GuardedFollower(const FollowerParams& params,
                                 std::shared_ptr<const MotionGuard> guard)
    : follower_(params), guard_(std::move(guard)) {}

FollowStatus GuardedFollower::step(const robot::Pose2D& pose, robot::Velocity& cmd) {
  robot::Velocity wanted;
  const FollowStatus status = follower_.step(pose, wanted);
  if (status != FollowStatus::kFollowing || !guard_) {
    cmd = wanted;
    return status;
  }
  robot::Velocity safe = guard_->filter(pose, wanted);
  const auto same = [](const robot::Velocity& a, const robot::Velocity& b) {
    return a.v == b.v && a.w == b.w;
  };
  // Cutting a corner too close: a nearer carrot, if the guard lets it pass (else the follower
  // goes on from its own command, as if it had not been asked).
  if (!close_ && wanted.v != 0 && !same(safe, wanted)) {
    const double lookahead = follower_.params().lookahead;
    bool nearer_passed = false;
    for (const double fraction : kNearerCarrots) {
      const robot::Velocity nearer = follower_.retry(pose, fraction * lookahead);
      const robot::Velocity checked = guard_->filter(pose, nearer);
      if (nearer.v != 0 && same(checked, nearer)) {
        wanted = safe = nearer;
        nearer_passed = true;
        break;
      }
    }
    if (!nearer_passed) follower_.retry(pose, lookahead);
  }
  // The guard stopping a forward command starts close following; the follower's own forward
  // command let through unchanged ends it. In between, the follower's commands are overruled
  // even when the guard would let a crawl of them through or they turn in place towards the
  // carrot: else they and the close following, turning towards the path just ahead, undid each
  // other beside a piece of furniture for seconds on end (office, a transit along a desk).
  if (wanted.v != 0 && safe.v == 0) close_ = true;
  if (wanted.v != 0 && same(safe, wanted)) close_ = false;
  if (!close_) {
    held_ticks_ = 0;
    cmd = safe;
    return FollowStatus::kFollowing;
  }
  bool held = false;
  cmd = closely(pose, held);
  held_ticks_ = held ? held_ticks_ + 1 : 0;
  if (held_ticks_ > kMaxHeldTicks) {
    held_ticks_ = 0;
    cmd = {};
    return FollowStatus::kBlocked;
  }
  return FollowStatus::kFollowing;
}

std::string GuardedFollower::failure(FollowStatus status, const std::string& what) const {
  switch (status) {
    case FollowStatus::kBlocked:
      return "blocked: following the " + what + " would touch a known obstacle";
    case FollowStatus::kStrayed: {
      std::ostringstream text;
      text.precision(2);
      text << "strayed " << follower_.deviation() << " m from the " << what;
      return text.str();
    }
    case FollowStatus::kNoPath:
      return "the " + what + " is empty";
    case FollowStatus::kFollowing:
    case FollowStatus::kArrived:
      break;
  }
  return "";
}

robot::Velocity GuardedFollower::closely(const robot::Pose2D& pose, bool& held) const {
  const FollowerParams& p = follower_.params();
  const planning::Point2 near = follower_.pointAhead(kCloseLookahead);
  const double error = robot::wrapAngle(std::atan2(near.y - pose.y, near.x - pose.x) - pose.theta);
  const double w = std::clamp(p.heading_gain * error, -p.max_angular_speed, p.max_angular_speed);
  if (std::fabs(error) > kAligned) return {0, w};  // turning to the path: not held
  const robot::Velocity creep = guard_->filter(pose, {kCreepSpeed, w});
  // Facing the path and still not let through: held, however small the turn that remains (it
  // shrinks with the heading error and would never end).
  held = creep.v == 0;
  return creep;
}

}  // namespace roomba_rrt::navigation
