#include "roomba_rrt/coverage/coverage_leaves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "roomba_rrt/coverage/joined_legs.h"
#include "roomba_rrt/navigation/guarded_follower.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::coverage {

using bt::inputPort;
using bt::InputPort;
using bt::NodeSpec;
using bt::outputPort;
using bt::OutputPort;
using bt::PortList;
using bt::Status;
using navigation::FollowStatus;
using navigation::NavContext;

Polyline remainingPath(const CoverageProgress& progress) {
  Polyline path;
  for (std::size_t k = progress.leg; k < progress.plan.legs.size(); ++k) {
    for (const Point2& p : progress.plan.legs[k].points) {
      if (path.empty() || path.back().x != p.x || path.back().y != p.y) path.push_back(p);
    }
  }
  return path;
}

const CoverageProgress* findProgress(const bt::Blackboard& board, const std::string& key) {
  const bt::Blackboard::EntryBase* entry = board.find(key);
  if (!entry || entry->type != typeid(CoverageProgress)) return nullptr;
  return board.get<CoverageProgress>(key);
}

namespace {

/// The planner of the leaves: given, or built from the world when the first leaf that plans is.
class LazyPlanner {
 public:
  LazyPlanner(world::World world, const CoverageOptions& options)
      : world_(std::move(world)), options_(options) {}
  explicit LazyPlanner(std::shared_ptr<const CoveragePlanner> planner)
      : planner_(std::move(planner)), given_(true) {}
  /// The clearance the rows keep (m).
  double clearance() const { return options().clearance; }
  /// The clearance rows along a wall keep (m).
  double edgeClearance() const { return options().edge_clearance; }
  const CoverageOptions& options() const { return planner_ ? planner_->options() : options_; }
  std::shared_ptr<const CoveragePlanner> get() {
    if (!planner_ && given_) {
      throw std::invalid_argument("coverage leaves: no coverage planner (only described)");
    }
    if (!planner_) planner_ = std::make_shared<const CoveragePlanner>(world_, options_);
    return planner_;
  }

 private:
  world::World world_;
  CoverageOptions options_;
  std::shared_ptr<const CoveragePlanner> planner_;
  bool given_ = false;  ///< the planner was given (perhaps null): never built here
};

/// How the cleaning drives on top of the follower's limits: like a robot vacuum, not a cautious
/// navigator. With navigation's limits a U-turn between two rows (stop, turn, 30 cm, turn, go)
/// took 5 s and the furnished room's rows twice the ideal time; with these about 2.5 s.
struct Driving {
  static constexpr double kAccel = 2.0;             ///< m/s²: starting and stopping at rows' ends
  static constexpr double kTurnSpeed = 2.0;         ///< rad/s: the Roomba's limit
  static constexpr double kTurnAccel = 16.0;        ///< rad/s²: kAccel at the wheels, 25 cm apart
  static constexpr double kTurnGain = 8.0;          ///< 1/s: turning in place towards a leg
  static constexpr double kEndTolerance = 0.01;     ///< m: rows end 1 cm from their end (the walls)
  static constexpr double kHeadingTolerance = 0.1;  ///< rad (legs end without a heading)
  /// The lookahead (m) on a path of joined legs (joined_legs.h): about the radius of its arcs
  /// (JoinRules::kTurnRadius), so that the robot turns where the arc does.
  static constexpr double kJoinedLookahead = 0.13;
  /// A leg with less progress than kMinProgress (m) in kStuckTime (s) fails: turning to a leg
  /// and braking at its end take about 2 s.
  static constexpr double kMinProgress = 0.01;
  static constexpr double kStuckTime = 10.0;
  /// A row along a wall (Leg::along_wall: 3 mm from it) is driven with a guard that rolls each
  /// command this many ticks ahead (others: one), so that a pose two ticks later than roomba_bt
  /// expects (roomba_coverage --lag 3 --predict 1) does not carry the robot into the wall. With
  /// one tick, a willow_full crop (11.82,8.73 to 19.64,16.40) bumped 7 times instead of once;
  /// the runs at the expected latency are the same.
  static constexpr int kEdgeGuardTicks = 3;

  static navigation::FollowerParams apply(navigation::FollowerParams p) {
    p.max_linear_accel = kAccel;
    p.max_angular_speed = kTurnSpeed;
    p.max_angular_accel = kTurnAccel;
    p.heading_gain = kTurnGain;
    p.xy_tolerance = kEndTolerance;
    p.yaw_tolerance = kHeadingTolerance;
    return p;
  }
};

/// The plan and its progress, which FollowCoverage and ResumeCoverage read and write.
bt::PortInfo progressPort() {
  return bt::inoutPort<CoverageProgress>("coverage", "the cleaning in progress");
}
bt::PortInfo poseInput(const char* description) {
  return inputPort<robot::Pose2D>("pose", description);
}
bt::PortInfo errorOutput(const char* description) {
  return outputPort<std::string>("error", description, "{error}");
}

class PlanCoverage final : public bt::LeafNode {
 public:
  static PortList providedPorts() {
    return {inputPort<robot::Pose2D>("start", "where to plan from (the robot's pose)"),
            outputPort<CoverageProgress>("coverage", "the new plan, nothing cleaned yet"),
            errorOutput("why there is nothing to clean")};
  }
  /// `given`: the progress to go on with instead of a plan (null: plan).
  PlanCoverage(const NodeSpec& spec, std::shared_ptr<const CoveragePlanner> planner,
               std::shared_ptr<const CoverageProgress> given)
      : LeafNode(spec.name),
        start_(spec.input<robot::Pose2D>("start")),
        coverage_(spec.output<CoverageProgress>("coverage")),
        error_(spec.output<std::string>("error")),
        planner_(std::move(planner)),
        given_(std::move(given)) {}

 private:
  Status onTick() override {
    const robot::Pose2D* start = start_.get();
    if (!start) {
      error_.set("no start pose to plan from");
      return Status::kFailure;
    }
    CoverageProgress& progress = coverage_.value();
    if (given_) {  // going on where another tree stopped
      progress = *given_;
      coverage_.commit();
      if (progress.done()) {
        error_.set("nothing left to clean");
        return Status::kFailure;
      }
      return Status::kSuccess;
    }
    progress = CoverageProgress{};
    progress.plan = planner_->plan({start->x, start->y});
    if (progress.plan.legs.empty()) {  // nothing to touch up either: done
      progress.touch_ups = CoverageProgress::kTouchUpPasses;
    }
    coverage_.commit();
    if (progress.plan.legs.empty()) {
      error_.set("nothing to clean: no floor can be reached from the start");
      return Status::kFailure;
    }
    return Status::kSuccess;
  }

  InputPort<robot::Pose2D> start_;
  OutputPort<CoverageProgress> coverage_;
  OutputPort<std::string> error_;
  std::shared_ptr<const CoveragePlanner> planner_;
  std::shared_ptr<const CoverageProgress> given_;
};

class FollowCoverage final : public bt::LeafNode {
 public:
  static PortList providedPorts() {
    return {progressPort(), poseInput("the robot's pose"),
            inputPort<double>("transit_speed", "how fast to drive between rows (m/s)", "0.8")
                .range(0.01, navigation::FollowerLimits::kMaxSpeed),
            errorOutput("why following failed")};
  }
  FollowCoverage(const NodeSpec& spec, NavContext& context,
                 const navigation::FollowerParams& follower,
                 std::shared_ptr<const navigation::MotionGuard> guard,
                 std::shared_ptr<const navigation::MotionGuard> edge_guard, double row_speed,
                 std::shared_ptr<LazyPlanner> planner)
      : LeafNode(spec.name),
        planner_(std::move(planner)),
        context_(context),
        coverage_(spec.output<CoverageProgress>("coverage")),
        pose_(spec.input<robot::Pose2D>("pose")),
        error_(spec.output<std::string>("error")),
        transit_speed_(spec.literal<double>("transit_speed")),
        row_speed_(row_speed),
        built_with_(follower),
        guard_(guard),
        edge_guard_(std::move(edge_guard)),
        follower_(Driving::apply(follower), std::move(guard)) {}

 private:
  void onEnter() override {
    following_ = kNone;
    follower_.resetHold();
    contact_ = context_.bumper.pressed;
  }

  /// True once the robot has made no progress along the leg for Driving::kStuckTime (it turns on
  /// the spot, or its wheels spin): the leg fails and the tree resumes from where it stands.
  bool stuck() {
    if (follower_.progress() > furthest_ + Driving::kMinProgress) {
      furthest_ = follower_.progress();
      still_ticks_ = 0;
      return false;
    }
    return ++still_ticks_ * follower_.params().dt() > Driving::kStuckTime;
  }

  Status onTick() override {
    const robot::Pose2D* pose = pose_.get();
    if (!coverage_.get() || !pose) {
      error_.set(!pose ? "no pose" : "no coverage plan to follow");
      return Status::kFailure;
    }
    CoverageProgress& progress = coverage_.value();
    const CoveragePlanner& planner = *planner_->get();
    planner.markSwept(progress.swept, {pose->x, pose->y});
    // A bump is the bumper pressed while following, not a contact there when it started (the
    // robot put down against a wall; the side of a wall the back-up did not leave): from that,
    // the legs lead away, and the guard keeps the robot from pushing into what it knows.
    const bool bumped = context_.bumper.pressed && !contact_;
    contact_ = context_.bumper.pressed;
    if (bumped) {
      ++progress.bumps;
      error_.set("bumped");
      return Status::kFailure;
    }
    while (progress.leg < progress.plan.legs.size()) {
      if (following_ != progress.leg) startLeg(progress);
      if (context_.speed_scale != applied_scale_) applyLimits();
      robot::Velocity cmd;
      const FollowStatus status = follower_.step(*pose, cmd);
      // Past the end of a joined leg: in the next one, on the same path.
      while (!ends_.empty() && follower_.progress() >= ends_.front() &&
             status == FollowStatus::kFollowing) {
        finishLeg(progress);
        following_ = progress.leg;
        ends_.erase(ends_.begin());
      }
      switch (status) {
        case FollowStatus::kFollowing:
          if (stuck()) {
            error_.set("no progress along the leg for " + util::show(Driving::kStuckTime) + " s");
            return Status::kFailure;
          }
          context_.cmd = cmd;
          context_.state = behavior::RoombaState::kMoveForward;  // cleaning on the move
          context_.state_name = &name();
          return Status::kRunning;
        case FollowStatus::kArrived:
        case FollowStatus::kNoPath:  // a leg without points: nothing to drive
          finishLeg(progress);
          ends_.clear();
          continue;
        case FollowStatus::kBlocked:
        case FollowStatus::kStrayed:
          error_.set(follower_.failure(status, "leg"));
          return Status::kFailure;
      }
    }
    progress.swept_fraction = planner.sweptFraction(progress.swept);
    return Status::kSuccess;
  }

  /// Starts the follower on the current leg, with the legs driven with it as one path
  /// (joinLegs: a U-turn, the way round an island, the loop along the walls): transits at
  /// transit_speed, rows at the cleaning speed; the leg advances as the robot's progress passes
  /// the end of each. A leg ends where it ends, in any heading: the next one turns towards its
  /// start and sets off once nearly facing it (the follower's rotate_threshold), much quicker
  /// than stopping on the next leg's heading first.
  void startLeg(const CoverageProgress& progress) {
    const Leg& leg = progress.plan.legs[progress.leg];
    JoinedLegs joined = joinLegs(progress.plan.legs, progress.leg, progress.touchingUp(),
                                 planner_->get()->freeSpace());
    path_ = std::move(joined.path);
    ends_ = std::move(joined.ends);
    robot::Pose2D goal{0, 0, std::nan("")};  // no heading to end with
    if (!path_.empty()) {
      goal.x = path_.back().x;
      goal.y = path_.back().y;
    }
    navigation::FollowerParams params = Driving::apply(
        context_.follower_version != 0 ? context_.follower : built_with_);  // retuned: NavBt
    params.max_linear_speed = joined.cleaning ? rowSpeed() : transit_speed_;
    if (!ends_.empty()) params.lookahead = Driving::kJoinedLookahead;
    leg_params_ = params;
    applyLimits();
    follower_.setGuard(leg.along_wall ? edge_guard_ : guard_);
    follower_.start(path_, goal, context_.previous_cmd);
    following_ = progress.leg;
    furthest_ = 0;
    still_ticks_ = 0;
  }

  /// The leg's limits, the speeds slowed for the latency of the loop (NavContext::speed_scale;
  /// on time, exactly the leg's).
  void applyLimits() {
    applied_scale_ = context_.speed_scale;
    navigation::FollowerParams params = leg_params_;
    if (applied_scale_ != 1) {
      params.max_linear_speed *= applied_scale_;
      params.max_angular_speed *= applied_scale_;
    }
    follower_.setParams(params);
  }

  /// The current leg is done: on to the next (a finished row ends the tries at resuming).
  static void finishLeg(CoverageProgress& progress) {
    if (progress.plan.legs[progress.leg].kind == Leg::Kind::kRow) progress.tries = 0;
    ++progress.leg;
  }

  /// The lab's forward_speed, as retuned (NavBt::setRoombaParams) or as built.
  double rowSpeed() const { return context_.params ? context_.params->forward_speed : row_speed_; }

  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::shared_ptr<LazyPlanner> planner_;
  NavContext& context_;
  OutputPort<CoverageProgress> coverage_;
  InputPort<robot::Pose2D> pose_;
  OutputPort<std::string> error_;
  double transit_speed_;
  double row_speed_;
  navigation::FollowerParams built_with_;                 ///< the follower's limits unless retuned
  std::shared_ptr<const navigation::MotionGuard> guard_;  ///< rows and transits
  std::shared_ptr<const navigation::MotionGuard> edge_guard_;  ///< rows along a wall
  navigation::GuardedFollower follower_;
  navigation::FollowerParams leg_params_;  ///< the leg's limits before the latency's factor
  double applied_scale_ = 1;               ///< the factor leg_params_ were applied with
  Polyline path_;                          ///< the leg being followed (the follower points into it)
  std::size_t following_ = kNone;          ///< the leg the follower was started on
  /// Arc lengths along path_ where the joined legs after the first start.
  std::vector<double> ends_;
  double furthest_ = 0;   ///< the most progress along path_ so far (m)
  int still_ticks_ = 0;   ///< ticks since it last grew by Driving::kMinProgress
  bool contact_ = false;  ///< the bumper was pressed at the last tick (or when the leaf started)
};

class PlanTouchUp final : public bt::LeafNode {
 public:
  static PortList providedPorts() {
    return {progressPort(), poseInput("where the robot is"),
            inputPort<int>("edge_cleaning_from",
                           "the first pass (1, 2, ...) with rows along the walls at the edge "
                           "clearance; the passes before it leave what only they sweep",
                           "1")
                .range(1, 1000),
            inputPort<double>("min_spot_area",
                              "the least spot the pass goes back for (m²); 0: the pass's own "
                              "(the large spots first, then every spot of 40 cm² or more)",
                              "0")
                .range(0, 1),
            errorOutput("why no touch-up can be planned")};
  }
  PlanTouchUp(const NodeSpec& spec, std::shared_ptr<LazyPlanner> planner)
      : LeafNode(spec.name),
        coverage_(spec.output<CoverageProgress>("coverage")),
        pose_(spec.input<robot::Pose2D>("pose")),
        error_(spec.output<std::string>("error")),
        edge_cleaning_from_(spec.literal<int>("edge_cleaning_from")),
        min_spot_area_(spec.literal<double>("min_spot_area")),
        planner_(std::move(planner)) {}

 private:
  Status onTick() override {
    const robot::Pose2D* pose = pose_.get();
    if (!coverage_.get() || !pose) {
      error_.set(!pose ? "no pose" : "no coverage plan to touch up");
      return Status::kFailure;
    }
    CoverageProgress& progress = coverage_.value();
    // Only once the plan in hand is driven, and only as many passes as CoverageProgress has.
    if (progress.leg < progress.plan.legs.size() ||
        progress.touch_ups >= CoverageProgress::kTouchUpPasses) {
      return Status::kSuccess;
    }
    progress.plan = planner_->get()->touchUp(
        progress.swept, {pose->x, pose->y},
        min_spot_area_ > 0 ? min_spot_area_
                           : CoverageProgress::kTouchUpSpotAreas[progress.touch_ups],
        progress.touch_ups + 1 >= edge_cleaning_from_);
    progress.leg = 0;
    ++progress.touch_ups;
    coverage_.commit();
    return Status::kSuccess;
  }

  OutputPort<CoverageProgress> coverage_;
  InputPort<robot::Pose2D> pose_;
  OutputPort<std::string> error_;
  const int edge_cleaning_from_;
  const double min_spot_area_;  ///< m²; 0: CoverageProgress::kTouchUpSpotAreas
  std::shared_ptr<LazyPlanner> planner_;
};

class ResumeCoverage final : public bt::LeafNode {
 public:
  static PortList providedPorts() {
    return {
        progressPort(), poseInput("where the robot stopped"),
        inputPort<int>("skip_after", "resumes without finishing a row before it is given up", "3")
            .range(1, 1000),
        errorOutput("why the coverage cannot be resumed")};
  }
  ResumeCoverage(const NodeSpec& spec, std::shared_ptr<const CoveragePlanner> planner)
      : LeafNode(spec.name),
        coverage_(spec.output<CoverageProgress>("coverage")),
        pose_(spec.input<robot::Pose2D>("pose")),
        error_(spec.output<std::string>("error")),
        skip_after_(spec.literal<int>("skip_after")),
        planner_(std::move(planner)) {}

 private:
  Status onTick() override {
    const robot::Pose2D* pose = pose_.get();
    if (!coverage_.get() || !pose) {
      error_.set(!pose ? "no pose" : "no coverage plan to resume");
      return Status::kFailure;
    }
    CoverageProgress& progress = coverage_.value();
    const std::vector<Leg>& legs = progress.plan.legs;
    std::size_t from = std::min(progress.leg, legs.size());
    if (++progress.tries >= skip_after_) {
      // Give up on the row being driven, or the one the transit led to: resume after it.
      while (from < legs.size() && legs[from].kind != Leg::Kind::kRow) ++from;
      if (from < legs.size() && !legs[from].points.empty()) {
        progress.skipped.emplace_back(legs[from].points.front(), legs[from].points.back());
      }
      from = std::min(from + 1, legs.size());
      ++progress.skipped_rows;
      progress.tries = 0;
    }
    progress.plan = planner_->resume(progress.plan, from, {pose->x, pose->y});
    progress.leg = 0;
    coverage_.commit();
    return Status::kSuccess;
  }

  OutputPort<CoverageProgress> coverage_;
  InputPort<robot::Pose2D> pose_;
  OutputPort<std::string> error_;
  int skip_after_;
  std::shared_ptr<const CoveragePlanner> planner_;
};

class CoverageDone final : public bt::ConditionNode {
 public:
  static PortList providedPorts() {
    return {inputPort<CoverageProgress>("coverage", "the cleaning in progress")};
  }
  explicit CoverageDone(const NodeSpec& spec)
      : ConditionNode(spec.name), coverage_(spec.input<CoverageProgress>("coverage")) {}

 private:
  Status onTick() override {
    const CoverageProgress* progress = coverage_.get();
    return progress && progress->done() ? Status::kSuccess : Status::kFailure;
  }
  InputPort<CoverageProgress> coverage_;
};

navigation::LeafRegistrar registrar(std::shared_ptr<LazyPlanner> planner,
                                    std::shared_ptr<const CoverageProgress> given) {
  return [planner, given](bt::TreeFactory& factory, const navigation::NavLeafConfig& config,
                          NavContext& context) {
    NavContext* ctx = &context;
    factory.registerNodeType<PlanCoverage>("PlanCoverage", [planner, given](const NodeSpec& spec) {
      return std::make_unique<PlanCoverage>(spec, planner->get(), given);
    });
    // The rows keep the clearance exactly: the guard keeps half of it, so that it catches a
    // follower that drifts towards the furniture but lets one on the row through. Rows along a
    // wall (edge cleaning) keep less: their own guard keeps half of that, looking further ahead.
    navigation::NavLeafConfig driving = config;
    driving.follower = Driving::apply(config.follower);
    const std::shared_ptr<const navigation::MotionGuard> guard =
        navigation::knownWorldGuard(driving, planner->clearance() / 2);
    const std::shared_ptr<const navigation::MotionGuard> edge_guard = navigation::knownWorldGuard(
        driving, planner->edgeClearance() / 2, Driving::kEdgeGuardTicks);
    const double row_speed = config.params.forward_speed;
    const navigation::FollowerParams follower = config.follower;
    factory.registerNodeType<FollowCoverage>(
        "FollowCoverage",
        [ctx, follower, guard, edge_guard, row_speed, planner](const NodeSpec& spec) {
          return std::make_unique<FollowCoverage>(spec, *ctx, follower, guard, edge_guard,
                                                  row_speed, planner);
        });
    factory.registerNodeType<PlanTouchUp>("PlanTouchUp", [planner](const NodeSpec& spec) {
      return std::make_unique<PlanTouchUp>(spec, planner);
    });
    factory.registerNodeType<ResumeCoverage>("ResumeCoverage", [planner](const NodeSpec& spec) {
      return std::make_unique<ResumeCoverage>(spec, planner->get());
    });
    factory.registerNodeType<CoverageDone>(
        "CoverageDone", [](const NodeSpec& spec) { return std::make_unique<CoverageDone>(spec); });
  };
}

}  // namespace

navigation::LeafRegistrar coverageLeaves(const world::World& world,
                                         const CoverageOptions& options) {
  return registrar(std::make_shared<LazyPlanner>(world, options), nullptr);
}

navigation::LeafRegistrar coverageLeaves(std::shared_ptr<const CoveragePlanner> planner) {
  return registrar(std::make_shared<LazyPlanner>(std::move(planner)), nullptr);
}

navigation::LeafRegistrar coverageLeaves(std::shared_ptr<const CoveragePlanner> planner,
                                         CoverageProgress progress) {
  return registrar(std::make_shared<LazyPlanner>(std::move(planner)),
                   std::make_shared<const CoverageProgress>(std::move(progress)));
}

}  // namespace roomba_rrt::coverage
