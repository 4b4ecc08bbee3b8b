#include "roomba_rrt/navigation/nav_leaves.h"

#include "roomba_rrt/navigation/guarded_follower.h"

#include <algorithm>
#include <cmath>

#include "roomba_rrt/behavior/motion_leaf.h"
#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::bt {

std::string LiteralParser<robot::Pose2D>::parse(const std::string& text, robot::Pose2D& out) {
  double v[3];
  std::size_t begin = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t end = i < 2 ? text.find(';', begin) : text.size();
    if (end == std::string::npos || (i == 2 && text.find(';', begin) != std::string::npos)) {
      return "must be a pose \"x;y;theta\", got '" + text + "'";
    }
    const std::string error = LiteralParser<double>::parse(text.substr(begin, end - begin), v[i]);
    if (!error.empty()) return "must be a pose \"x;y;theta\" of finite numbers, got '" + text + "'";
    begin = end + 1;
  }
  out = {v[0], v[1], v[2]};
  return "";
}

}  // namespace roomba_rrt::bt

namespace roomba_rrt::navigation {

const char* toString(GoalOutcome outcome) {
  switch (outcome) {
    case GoalOutcome::kNone:
      return "none";
    case GoalOutcome::kActive:
      return "active";
    case GoalOutcome::kSucceeded:
      return "succeeded";
    case GoalOutcome::kAborted:
      return "aborted";
  }
  return "?";
}

namespace {

using bt::inputPort;
using bt::InputPort;
using bt::NodeSpec;
using bt::outputPort;
using bt::OutputPort;
using bt::PortList;
using bt::Status;

/// A leaf that reports itself as the active leaf (~state) while it runs.
class NavLeaf : public bt::LeafNode {
 public:
  NavLeaf(const std::string& name, NavContext& context) : LeafNode(name), context_(context) {}

 protected:
  void report() { context_.state_name = &name(); }
  NavContext& context_;
};

class ComputePath final : public NavLeaf {
 public:
  static PortList providedPorts() {
    return {inputPort<robot::Pose2D>("start", "where to plan from (the robot's pose)"),
            inputPort<robot::Pose2D>("goal", "where to plan to"),
            outputPort<Path>("path", "the plan, start to goal"),
            outputPort<std::string>("error", "why planning failed", "{error}")};
  }
  ComputePath(const NodeSpec& spec, NavContext& context, std::unique_ptr<PathPlanner> planner,
              std::shared_ptr<const PathChecker> known_world)
      : NavLeaf(spec.name, context),
        start_(spec.input<robot::Pose2D>("start")),
        goal_(spec.input<robot::Pose2D>("goal")),
        path_(spec.output<Path>("path")),
        error_(spec.output<std::string>("error")),
        planner_(std::move(planner)),
        known_world_(std::move(known_world)) {
    if (!planner_) throw std::invalid_argument("ComputePath: no planner");
  }

 private:
  void onEnter() override { requested_ = false; }
  Status onTick() override {
    if (!requested_) {
      const robot::Pose2D* start = start_.get();
      const robot::Pose2D* goal = goal_.get();
      if (!start || !goal) {
        error_.set(start ? "no goal to plan to" : "no start pose to plan from");
        return Status::kFailure;
      }
      planner_->request({start->x, start->y}, {goal->x, goal->y});
      requested_ = true;
      report();
      return Status::kRunning;
    }
    if (!planner_->poll(reply_)) {
      report();
      return Status::kRunning;
    }
    if (!reply_.success) {
      error_.set("no path: " + reply_.message);
      return Status::kFailure;
    }
    // A replan while driving keeps the current path unless the new one is shorter than what is
    // left of it (and the current one is still free): RRT's plans differ at random, and a robot
    // handed every new one dithers between the two ways round an obstacle.
    if (!keepCurrentPath()) {
      std::swap(path_.value(), reply_.path);  // recycles the old path's storage
      path_.commit();
    }
    return Status::kSuccess;
  }

  bool keepCurrentPath() {
    const Path& current = path_.value();
    if (current.size() < 2 || reply_.path.size() < 2) return false;
    const robot::Pose2D* goal = goal_.get();
    if (!goal || current.back().x != goal->x || current.back().y != goal->y) return false;
    const planning::Point2 robot = reply_.path.front();
    // What is left of the current path: from the robot's projection on its nearest segment on.
    const std::size_t nearest = nearestSegment(current, robot);
    const planning::Point2 p =
        geometry::closestPoint(planning::Segment{current[nearest], current[nearest + 1]}, robot);
    double left = planning::distance(robot, p) + planning::distance(p, current[nearest + 1]);
    for (std::size_t i = nearest + 1; i + 1 < current.size(); ++i) {
      left += planning::distance(current[i], current[i + 1]);
    }
    return left <= geometry::pathLength(reply_.path) &&
           (!known_world_ || known_world_->isPathFree(current, nearest + 1));
  }
  void onHalt() override { planner_->cancel(); }

  InputPort<robot::Pose2D> start_, goal_;
  OutputPort<Path> path_;
  OutputPort<std::string> error_;
  std::unique_ptr<PathPlanner> planner_;
  std::shared_ptr<const PathChecker> known_world_;
  PlanReply reply_;
  bool requested_ = false;
};

class FollowPath final : public NavLeaf {
 public:
  static PortList providedPorts() {
    return {inputPort<Path>("path", "the path to follow"),
            inputPort<robot::Pose2D>("goal", "the goal pose (its heading is the final one)"),
            inputPort<robot::Pose2D>("pose", "the robot's pose"),
            outputPort<std::string>("error", "why following failed", "{error}")};
  }
  FollowPath(const NodeSpec& spec, NavContext& context, const FollowerParams& params,
             std::shared_ptr<const MotionGuard> guard)
      : NavLeaf(spec.name, context),
        path_(spec.input<Path>("path")),
        goal_(spec.input<robot::Pose2D>("goal")),
        pose_(spec.input<robot::Pose2D>("pose")),
        error_(spec.output<std::string>("error")),
        follower_(params, std::move(guard)) {}

 private:
  void onEnter() override {
    path_writes_ = 0;
    follower_.resetHold();
  }
  Status onTick() override {
    const Path* path = path_.get();
    const robot::Pose2D* goal = goal_.get();
    const robot::Pose2D* pose = pose_.get();
    if (!path || !goal || !pose) {
      error_.set(!path ? "no path to follow" : !goal ? "no goal" : "no pose");
      return Status::kFailure;
    }
    if (context_.bumper.pressed) {
      error_.set("bumped");
      return Status::kFailure;
    }
    if (context_.follower_version != follower_version_) {  // tuned while running
      follower_.setParams(context_.follower);
      follower_version_ = context_.follower_version;
    }
    if (path_.writes() != path_writes_) {  // a new plan: follow it from here
      path_writes_ = path_.writes();
      follower_.start(*path, *goal, context_.previous_cmd);
    }
    robot::Velocity cmd;
    const FollowStatus status = follower_.step(*pose, cmd);
    switch (status) {
      case FollowStatus::kFollowing:
        context_.cmd = cmd;
        report();
        return Status::kRunning;
      case FollowStatus::kArrived:
        return Status::kSuccess;
      case FollowStatus::kBlocked:  // the recovery replans from where the robot is
      case FollowStatus::kStrayed:
      case FollowStatus::kNoPath:
        error_.set(follower_.failure(status, "path"));
        return Status::kFailure;
    }
    return Status::kFailure;
  }

  InputPort<Path> path_;
  InputPort<robot::Pose2D> goal_, pose_;
  OutputPort<std::string> error_;
  GuardedFollower follower_;
  std::uint64_t path_writes_ = 0;
  std::uint64_t follower_version_ = 0;  ///< the context's follower_version in force
};

class GoalUpdated final : public bt::ConditionNode {
 public:
  static PortList providedPorts() { return {inputPort<robot::Pose2D>("goal", "the goal")}; }
  explicit GoalUpdated(const NodeSpec& spec)
      : ConditionNode(spec.name),
        goal_(spec.input<robot::Pose2D>("goal")),
        clock_(*spec.blackboard) {}

 private:
  Status onTick() override {
    const std::uint64_t now = clock_.tick();
    const std::uint64_t writes = goal_.writes();
    // A run starts when it was not ticked on the previous tick (Nav2: on leaving IDLE).
    const bool updated = last_tick_ != 0 && now == last_tick_ + 1 && writes != seen_;
    last_tick_ = now;
    seen_ = writes;
    return updated ? Status::kSuccess : Status::kFailure;
  }
  InputPort<robot::Pose2D> goal_;
  const bt::Blackboard& clock_;
  std::uint64_t seen_ = 0;
  std::uint64_t last_tick_ = 0;
};

class HasGoal final : public bt::ConditionNode {
 public:
  static PortList providedPorts() { return {inputPort<robot::Pose2D>("goal", "the goal")}; }
  explicit HasGoal(const NodeSpec& spec)
      : ConditionNode(spec.name), goal_(spec.input<robot::Pose2D>("goal")) {}

 private:
  Status onTick() override { return goal_.get() ? Status::kSuccess : Status::kFailure; }
  InputPort<robot::Pose2D> goal_;
};

class IsBumped final : public bt::ConditionNode {
 public:
  static PortList providedPorts() { return {}; }
  IsBumped(const NodeSpec& spec, const NavContext& context)
      : ConditionNode(spec.name), context_(context) {}

 private:
  Status onTick() override { return context_.bumper.pressed ? Status::kSuccess : Status::kFailure; }
  const NavContext& context_;
};

class IsPathValid final : public bt::ConditionNode {
 public:
  static PortList providedPorts() {
    return {inputPort<Path>("path", "the path to check"),
            outputPort<std::string>("error", "why the path is not valid", "{error}")};
  }
  IsPathValid(const NodeSpec& spec, std::shared_ptr<const PathChecker> checker)
      : ConditionNode(spec.name),
        path_(spec.input<Path>("path")),
        error_(spec.output<std::string>("error")),
        checker_(std::move(checker)) {}

 private:
  Status onTick() override {
    const Path* path = path_.get();
    if (!path) {
      error_.set("no path to check");
      return Status::kFailure;
    }
    if (checker_ && !checker_->isPathFree(*path, 0)) {
      error_.set("the path is blocked");
      return Status::kFailure;
    }
    return Status::kSuccess;
  }
  InputPort<Path> path_;
  OutputPort<std::string> error_;
  std::shared_ptr<const PathChecker> checker_;
};

/// GoalSucceeded (kSucceeded) and GoalAborted (kAborted): end the goal and record how.
template <GoalOutcome kOutcome>
class EndGoal final : public bt::LeafNode {
 public:
  static PortList providedPorts() {
    PortList ports{inputPort<robot::Pose2D>("goal", "the goal")};
    if (kOutcome == GoalOutcome::kAborted) {
      ports.push_back(inputPort<std::string>("error", "why", "{error}"));
    }
    return ports;
  }
  EndGoal(const NodeSpec& spec, NavContext& context)
      : LeafNode(spec.name), context_(context), goal_entry_(spec.input<robot::Pose2D>("goal")) {
    if (kOutcome == GoalOutcome::kAborted) error_ = spec.input<std::string>("error");
    std::string key;
    if (!bt::parseBlackboardKey(spec.attributes.at("goal"), key)) {
      throw std::invalid_argument("port 'goal' needs a blackboard key like {goal}");
    }
    goal_ = &spec.blackboard->declare<robot::Pose2D>(key);
  }

 private:
  Status onTick() override {
    if (!goal_->get()) return Status::kFailure;  // no goal to end
    goal_->clear();
    context_.outcome = kOutcome;
    if (kOutcome == GoalOutcome::kSucceeded) {
      context_.message.clear();
      return Status::kSuccess;
    }
    const std::string* error = error_.get();
    context_.message = error && !error->empty() ? *error : "navigation failed";
    return Status::kFailure;
  }
  NavContext& context_;
  InputPort<robot::Pose2D> goal_entry_;
  InputPort<std::string> error_;
  bt::Blackboard::Entry<robot::Pose2D>* goal_ = nullptr;
};

template <class Node, class... Args>
bt::TreeFactory::Builder make(Args... args) {
  return [args...](const NodeSpec& spec) { return std::make_unique<Node>(spec, args...); };
}

}  // namespace

std::shared_ptr<const MotionGuard> knownWorldGuard(const NavLeafConfig& config, double margin,
                                                   int ticks) {
  if (!config.known_world) return nullptr;
  return std::make_shared<MotionGuard>(config.known_world->world(), config.follower.rate,
                                       config.follower.max_linear_accel, margin, ticks);
}

void registerNavLeaves(bt::TreeFactory& factory, const NavLeafConfig& config, NavContext& context) {
  validate(config.params);
  validate(config.follower);
  if (!config.planners) throw std::invalid_argument("registerNavLeaves: no planner factory");
  const PlannerFactory planners = config.planners;
  const std::shared_ptr<const PathChecker> known_world = config.known_world;
  NavContext* ctx = &context;
  factory.registerNodeType<ComputePath>(
      "ComputePath", [planners, known_world, ctx](const NodeSpec& spec) {
        return std::make_unique<ComputePath>(spec, *ctx, planners(), known_world);
      });
  const FollowerParams follower = config.follower;
  const std::shared_ptr<const MotionGuard> guard = knownWorldGuard(config);
  factory.registerNodeType<FollowPath>("FollowPath", [follower, ctx, guard](const NodeSpec& spec) {
    return std::make_unique<FollowPath>(spec, *ctx, follower, guard);
  });
  const double rate = config.params.rate;
  factory.registerNodeWithPorts(
      "BackUp", bt::NodeKind::kLeaf,
      [rate, ctx](const NodeSpec& spec) {
        return std::make_unique<behavior::MotionLeaf<behavior::BackUp>>(
            spec.name, behavior::RoombaState::kGoBack,
            behavior::BackUp(spec.literal<double>("backup_dist"),
                             spec.literal<double>("backup_speed"), rate),
            *ctx);
      },
      {inputPort<double>("backup_dist", "how far to back up (m)", "0.15").range(0.0, 5.0),
       inputPort<double>("backup_speed", "how fast (m/s)", "0.1").range(0.01, 1.0)});
  factory.registerNodeWithPorts(
      "Spin", bt::NodeKind::kLeaf,
      [rate, ctx](const NodeSpec& spec) {
        return std::make_unique<behavior::MotionLeaf<behavior::Spin>>(
            spec.name, behavior::RoombaState::kRotate,
            behavior::Spin(spec.literal<double>("spin_dist"), spec.literal<double>("spin_speed"),
                           1.0 / rate),
            *ctx);
      },
      {inputPort<double>("spin_dist", "how far to turn (rad, positive: left)", "1.57")
           .range(-31.5, 31.5),
       inputPort<double>("spin_speed", "how fast (rad/s)", "1.0").range(0.01, 10.0)});
  factory.registerNodeType<GoalUpdated>("GoalUpdated", make<GoalUpdated>());
  factory.registerNodeType<HasGoal>("HasGoal", make<HasGoal>());
  factory.registerNodeType<IsBumped>(
      "IsBumped", [ctx](const NodeSpec& spec) { return std::make_unique<IsBumped>(spec, *ctx); });
  factory.registerNodeType<IsPathValid>("IsPathValid", [known_world](const NodeSpec& spec) {
    return std::make_unique<IsPathValid>(spec, known_world);
  });
  using GoalSucceeded = EndGoal<GoalOutcome::kSucceeded>;
  using GoalAborted = EndGoal<GoalOutcome::kAborted>;
  factory.registerNodeType<GoalSucceeded>("GoalSucceeded", [ctx](const NodeSpec& spec) {
    return std::make_unique<GoalSucceeded>(spec, *ctx);
  });
  factory.registerNodeType<GoalAborted>("GoalAborted", [ctx](const NodeSpec& spec) {
    return std::make_unique<GoalAborted>(spec, *ctx);
  });
  for (const LeafRegistrar& more : config.more_leaves) more(factory, config, context);
}

}  // namespace roomba_rrt::navigation
