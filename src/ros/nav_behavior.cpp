#include "nav_behavior.h"

#include <actionlib/server/simple_action_server.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <roomba_rrt/CoverageReport.h>
#include <roomba_rrt/NavFollowerConfig.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "behavior_node.h"
#include "map_messages.h"
#include "message_parts.h"
#include "nav_ros.h"
#include "planner_ros.h"
#include "reconfigure.h"
#include "roomba_rrt/coverage/coverage_leaves.h"
#include "roomba_rrt/exploration/bump_clean.h"
#include "roomba_rrt/exploration/clean_known_map.h"
#include "roomba_rrt/exploration/explore_clean.h"
#include "roomba_rrt/exploration/navigate_unknown.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/util/require.h"
#include "roomba_rrt/world/world_file.h"
#include "roomba_rrt/world_planning/room_problem.h"
#include "scan_input.h"

namespace roomba_rrt::nav_node {
namespace {

using navigation::InProcessPlanner;
using MoveBaseServer = actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction>;

constexpr int kFeedbackEvery = 6;  ///< ticks between feedback messages (10 Hz at 60 Hz)
const std::string kIdle = "Idle";

/// What makeNavBehavior reads from the parameters besides the tree.
struct Settings {
  world::World world;
  double clearance = navigation::kDefaultClearance;
  std::string global_frame = "map", robot_frame = "base_link";
  navigation::NavLeafConfig config;
  /// ~unknown: a home the robot does not know, with the map it builds from `scan`; world holds
  /// only its robot then. With a cleaning tree it explores and cleans on its own
  /// (exploration::ExploreClean); with a navigation tree it drives to goals on that map
  /// (exploration::NavigateUnknown).
  bool unknown = false;
  bool cleaning = false;  ///< ~unknown with a cleaning tree (one with coverage leaves)
  exploration::ExploreCleanTrees trees;  ///< cleaning: both; navigation: explore is the tree
  /// ~known_map: the map of the home the robot is given with ~unknown (perhaps stale: its walls,
  /// not its furniture); null without one. Cleaning plans on it at once
  /// (exploration::CleanKnownMap), navigation starts its map from it.
  std::shared_ptr<const exploration::KnownMap> known;
  double transform_timeout = 0.2;  ///< s a scan waits for tf (roomba_mapper's ~transform_timeout)
};

/// The ~plan_path client behind ComputePath: one persistent connection per planner, made again
/// after a failed call (rrt_planner restarted). Runs on the planner's worker thread.
class PlanPathClient {
 public:
  PlanPathClient(std::string service, PlanTarget target, planning::PlannerOptions options)
      : service_(std::move(service)), target_(std::move(target)), options_(std::move(options)) {}

  navigation::PlanReply operator()(const planning::Point2& start, const planning::Point2& goal,
                                   std::uint32_t seed) {
    if (!client_.isValid()) client_ = ros::NodeHandle().serviceClient<PlanPath>(service_, true);
    PlanPath srv;
    srv.request = planRequest(start, goal, seed, target_, options_);
    if (!client_.call(srv)) {
      client_.shutdown();
      navigation::PlanReply reply;
      reply.message = "planner: the service " + service_ +
                      " did not answer (is rrt_planner running? or set ~planner:=in_process)";
      return reply;
    }
    return toPlanReply(srv.response);
  }

 private:
  std::string service_;
  PlanTarget target_;                 ///< the planner's scenario and the robot
  planning::PlannerOptions options_;  ///< step, iterations, tolerance of every request
  ros::ServiceClient client_;
};

class NavBehavior final : public behavior::RoombaBehavior {
 public:
  NavBehavior(const behavior::RoombaParams& params, std::uint32_t seed,
              const std::string& tree_file, Settings settings, nodes::CommandOutput& output)
      : RoombaBehavior(params, seed),
        output_(output),
        settings_(std::move(settings)),
        seed_(seed),
        listener_(buffer_),
        server_(nh_, "move_base", false),
        scans_(buffer_, settings_.global_frame, settings_.transform_timeout, "roomba_bt") {
    if (settings_.unknown && settings_.cleaning && byTouch()) {
      // No lidar: the robot's own short rangers (the IR light bumper's ir_bumper), by name.
      for (const sensors::RangeSensorSpec& sensor : settings_.world.robot().sensors) {
        touch_subs_.push_back(nh_.subscribe(sensor.name, 5, &NavBehavior::onScan, this));
      }
    } else if (settings_.unknown) {
      scan_sub_ = nh_.subscribe("scan", 5, &NavBehavior::onScan, this);
      if (settings_.known) {  // as map_server serves it: for rviz, beside the map being built
        known_map_pub_ = ros::NodeHandle("~").advertise<nav_msgs::OccupancyGrid>("known_map", 1,
                                                                                 /*latch=*/true);
        known_map_pub_.publish(nodes::toMapMessage(*settings_.known->grid, ros::Time::now()));
      }
    } else {
      nav_ = std::make_unique<navigation::NavBt>(settings_.config, seed, tree_file);
    }
    context_.state_name = &kIdle;
    plan_pub_ = ros::NodeHandle("~").advertise<nav_msgs::Path>("plan", 1, /*latch=*/true);
    coverage_pub_ =
        ros::NodeHandle("~").advertise<nav_msgs::Path>("coverage_path", 1, /*latch=*/true);
    report_pub_ = ros::NodeHandle("~").advertise<roomba_rrt::CoverageReport>("coverage_report", 1,
                                                                             /*latch=*/true);
    // /move_base_simple/goal becomes a goal of the action, as in move_base, so that a goal from
    // rviz preempts an action client's goal and is reported on move_base/status.
    action_goal_pub_ = nh_.advertise<move_base_msgs::MoveBaseActionGoal>("move_base/goal", 1);
    simple_goal_sub_ = nh_.subscribe("move_base_simple/goal", 1, &NavBehavior::onSimpleGoal, this);
    server_.registerGoalCallback([this] { onGoal(); });
    server_.registerPreemptCallback([this] { onPreempt(); });
    server_.start();
    startFollowerReconfigure();
  }

  /// The tree, to watch and record; none with ~unknown (its trees come and go as the map grows).
  bt::Tree* behaviorTree() override { return nav_ ? &nav_->tree() : nullptr; }

  /// The lab's constants for the cleaning leaves (BehaviorNode's dynamic_reconfigure).
  void setParams(const behavior::RoombaParams& params) override {
    if (nav_) nav_->setRoombaParams(params);
    if (explore_) explore_->setParams(params);
    if (known_) known_->setParams(params);
    RoombaBehavior::setParams(params);
  }

  robot::Velocity tick(const robot::BumperState& bumper) override {
    bumper_ = bumper;
    return step();
  }

 private:
  robot::Velocity step() {
    robot::Pose2D pose;
    double stamp = 0;
    try {
      const auto t =
          buffer_.lookupTransform(settings_.global_frame, settings_.robot_frame, ros::Time(0));
      geometry_msgs::Pose p;
      p.position.x = t.transform.translation.x;
      p.position.y = t.transform.translation.y;
      p.orientation = t.transform.rotation;
      pose = toPose2D(p);
      stamp = t.header.stamp.toSec();
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "no robot pose (%s -> %s): %s; standing still",
                        settings_.global_frame.c_str(), settings_.robot_frame.c_str(), e.what());
      return {};
    }
    // How late the commands land (the cleaning slows down when they do): the tick's time and
    // the stamp of the pose it acts on, both the simulator's clock.
    const double now = ros::Time::now().toSec();
    robot::Velocity cmd;
    navigation::NavBt* active = nav_.get();
    if (nav_) {
      nav_->observeTiming(now, stamp);
      cmd = nav_->tick(bumper_, pose);
      // ~state names the active leaf; "Idle" once the tree is done and the robot stands (the
      // tree keeps the last leaf's name, e.g. FollowPath at the goal): not between a back-up and
      // the resume (NavBt::idle).
      context_.state_name = nav_->idle() ? &kIdle : &nav_->stateName();
    } else if (settings_.cleaning && settings_.known) {
      if (!known_ && !startCleaningKnown(pose)) return {};
      scans_.drain(ros::Time::now());
      cmd = known_->tick(now, bumper_, pose, stamp);
      context_.state_name = known_->done() ? &kIdle : &known_->stateName();
      active = known_->activeTree();
    } else if (settings_.cleaning && byTouch()) {
      if (!touch_) startCleaningByTouch(pose);
      scans_.drain(ros::Time::now());
      cmd = touch_->tick(now, bumper_, pose);
      context_.state_name = touch_->done() ? &kIdle : &touch_->stateName();
      active = nullptr;
      if (touch_->done() && !reported_) {
        reported_ = true;
        const double cell = touch_->map().resolution();
        ROS_INFO("roomba_bt: cleaned by touch: %.1f m² swept, %d moves, done at %.0f s",
                 touch_->map().sweptCells() * cell * cell, touch_->moves(), touch_->doneAt());
      }
    } else if (settings_.cleaning) {
      if (!explore_) startExploring(pose);
      scans_.drain(ros::Time::now());  // a scan that came before its tf: into the map now
      cmd = explore_->tick(now, bumper_, pose, stamp);
      context_.state_name = explore_->done() ? &kIdle : &explore_->stateName();
      active = explore_->activeTree();
    } else {
      if (!to_goal_ && !startNavigating(pose)) return {};
      scans_.drain(ros::Time::now());
      cmd = to_goal_->tick(now, bumper_, pose, stamp);
      context_.state_name = &to_goal_->stateName();  // Idle without a goal
      active = to_goal_->tree();
    }
    if (active) {
      publishPlan(*active);
      publishCoveragePath(*active);
      reportCoverage(*active);
    }
    report(pose);
    return cmd;
  }

  /// ~unknown: the map starts round the robot's first pose.
  void startExploring(const robot::Pose2D& pose) {
    world::RobotSpec robot = settings_.world.robot();
    robot.initial_pose = pose;
    explore_ = std::make_unique<exploration::ExploreClean>(
        robot, settings_.world.coverage_cell_size, params(), seed_, settings_.config.pose_latency,
        settings_.trees);
    ROS_INFO("roomba_bt: exploring from (%.2f, %.2f) with the map built from %s", pose.x, pose.y,
             scan_sub_.getTopic().c_str());
  }

  /// ~unknown with a cleaning tree, no lidar (exploration::cleansByTouch) and no known map: the
  /// classic Roomba's online boustrophedon from the robot's first pose.
  bool byTouch() const {
    return !settings_.known && exploration::cleansByTouch(settings_.world.robot());
  }
  void startCleaningByTouch(const robot::Pose2D& pose) {
    world::RobotSpec robot = settings_.world.robot();
    robot.initial_pose = pose;
    touch_ = std::make_unique<exploration::BumpClean>(robot, params());
    ROS_INFO("roomba_bt: no lidar: cleaning by touch from (%.2f, %.2f) with the bumper%s", pose.x,
             pose.y, robot.sensors.empty() ? " alone" : " and the robot's short rangers");
  }

  /// ~unknown with a navigation tree: the map starts round the robot's first pose (from
  /// ~known_map when given); goals are taken from then on. False while the known map does not
  /// fit the robot's pose (said, and the robot stands).
  bool startNavigating(const robot::Pose2D& pose) {
    world::RobotSpec robot = settings_.world.robot();
    robot.initial_pose = pose;
    try {
      to_goal_ = std::make_unique<exploration::NavigateUnknown>(
          robot, params(), seed_, settings_.config.pose_latency, settings_.trees.explore,
          settings_.known.get());
    } catch (const util::InvalidInput& e) {
      knownMapRefused(pose, e);
      return false;
    }
    to_goal_->setFollowerParams(settings_.config.follower);
    ROS_INFO("roomba_bt: mapping from (%.2f, %.2f) with %s%s; goals are planned on that map",
             pose.x, pose.y, scan_sub_.getTopic().c_str(),
             settings_.known ? (", starting from " + settings_.known->file).c_str() : "");
    return true;
  }

  /// ~unknown ~known_map with a cleaning tree: the rows planned on the known map at once. False
  /// while the known map does not fit the robot's pose (said, and the robot stands).
  bool startCleaningKnown(const robot::Pose2D& pose) {
    world::RobotSpec robot = settings_.world.robot();
    robot.initial_pose = pose;
    try {
      known_ = std::make_unique<exploration::CleanKnownMap>(
          robot, *settings_.known, settings_.world.coverage_cell_size, params(), seed_,
          settings_.config.pose_latency, settings_.trees.clean);
    } catch (const util::InvalidInput& e) {
      knownMapRefused(pose, e);
      return false;
    }
    ROS_INFO("roomba_bt: cleaning from (%.2f, %.2f) on %s and the map built from %s", pose.x,
             pose.y, settings_.known->file.c_str(), scan_sub_.getTopic().c_str());
    return true;
  }

  /// The known map does not fit where tf puts the robot (a map of another home, another frame).
  static void knownMapRefused(const robot::Pose2D& pose, const util::InvalidInput& e) {
    ROS_ERROR_THROTTLE(5.0, "roomba_bt: ~known_map: %s (the robot at (%.2f, %.2f)); standing still",
                       e.what(), pose.x, pose.y);
  }

  /// ~unknown: a scan into the map, with its frame's pose in the global frame at its stamp.
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    if (!explore_ && !to_goal_ && !known_ && !touch_) return;  // no pose yet: nowhere to start
    scans_.push(scan->header.frame_id, scan->header.stamp,
                [this, scan](const geometry_msgs::Transform& transform) {
                  robot::Pose2D sensor;
                  std::string why = nodes::planarPose(transform, &sensor);
                  if (why.empty()) {
                    const mapping::ScanView view = nodes::scanView(*scan);
                    why = touch_     ? touch_->addScan(sensor, view)
                          : explore_ ? explore_->addScan(sensor, view)
                          : known_   ? known_->addScan(sensor, view)
                                     : to_goal_->addScan(sensor, view);
                  }
                  if (!why.empty())
                    ROS_WARN_THROTTLE(5.0, "roomba_bt: scan skipped: %s", why.c_str());
                });
  }

  /// ~coverage_path: what is left of the cleaning tree's coverage plan, from the leg being
  /// driven on, whenever the plan or the leg changes (empty once everything is driven).
  void publishCoveragePath(navigation::NavBt& nav) {
    const coverage::CoverageProgress* progress = coverage::findProgress(nav.tree().blackboard());
    if (progress == nullptr) return;
    const CoverageMark mark{progress->plan.legs.data(), progress->plan.legs.size(), progress->leg};
    if (mark == coverage_mark_) return;
    coverage_mark_ = mark;
    coverage_pub_.publish(planner_node::toPathMessage(coverage::remainingPath(*progress),
                                                      settings_.global_frame, ros::Time::now()));
  }

  /// Once the cleaning is done: what it reached and what it gave up, on ~coverage_report and in
  /// a line (a warning when rows were given up). Until then, the latency's worst.
  void reportCoverage(navigation::NavBt& nav) {
    const coverage::CoverageProgress* progress = coverage::findProgress(nav.tree().blackboard());
    if (progress == nullptr) return;
    max_latency_ = std::max(max_latency_, nav.latency());
    slowest_ = std::min(slowest_, nav.speedScale());
    if (!progress->done()) {
      reported_ = false;
      return;
    }
    if (reported_) return;
    reported_ = true;
    roomba_rrt::CoverageReport msg;
    msg.header.stamp = ros::Time::now();
    msg.header.frame_id = settings_.global_frame;
    msg.coverage = static_cast<float>(progress->swept_fraction);
    msg.bumps = static_cast<std::uint32_t>(progress->bumps);
    msg.skipped_rows = static_cast<std::uint32_t>(progress->skipped_rows);
    std::ostringstream where;
    for (const auto& [from, to] : progress->skipped) {
      geometry_msgs::Point a, b;
      a.x = from.x;
      a.y = from.y;
      b.x = to.x;
      b.y = to.y;
      msg.skipped_from.push_back(a);
      msg.skipped_to.push_back(b);
      where << (where.tellp() > 0 ? ", " : ": ") << "(" << from.x << ", " << from.y << ")-(" << to.x
            << ", " << to.y << ")";
    }
    msg.latency = static_cast<float>(max_latency_);
    msg.slowest_speed_scale = static_cast<float>(slowest_);
    report_pub_.publish(msg);
    const std::string line =
        "cleaning done: " + util::show(100 * progress->swept_fraction) + " % of the floor swept, " +
        std::to_string(progress->bumps) + " bumps, " + std::to_string(progress->skipped_rows) +
        " rows given up" + where.str() + "; commands up to " + util::show(max_latency_) +
        " s late, speeds down to " + util::show(100 * slowest_) + " %";
    if (progress->skipped_rows > 0) {
      ROS_WARN("%s", line.c_str());
    } else {
      ROS_INFO("%s", line.c_str());
    }
  }

  navigation::GoalOutcome goalOutcome() const {
    return nav_ ? nav_->outcome() : to_goal_->outcome();
  }
  const std::string& goalMessage() const { return nav_ ? nav_->message() : to_goal_->message(); }
  void cancelGoal() {
    if (nav_) nav_->cancelGoal();
    if (to_goal_) to_goal_->cancelGoal();
  }

  /// The goal's outcome to the action client, or feedback while it runs.
  void report(const robot::Pose2D& pose) {
    if (!goal_open_) return;
    move_base_msgs::MoveBaseResult result;
    switch (goalOutcome()) {
      case navigation::GoalOutcome::kSucceeded:
        goal_open_ = false;
        ROS_INFO("goal reached at (%.2f, %.2f)", pose.x, pose.y);
        server_.setSucceeded(result, "reached the goal");
        return;
      case navigation::GoalOutcome::kAborted:
        goal_open_ = false;
        ROS_WARN("goal aborted: %s", goalMessage().c_str());
        server_.setAborted(result, goalMessage());
        return;
      case navigation::GoalOutcome::kNone:
      case navigation::GoalOutcome::kActive:
        break;
    }
    if (++ticks_since_feedback_ < kFeedbackEvery) return;
    ticks_since_feedback_ = 0;
    move_base_msgs::MoveBaseFeedback feedback;
    feedback.base_position = toPoseStamped(pose, settings_.global_frame, ros::Time::now());
    server_.publishFeedback(feedback);
  }

  void publishPlan(const navigation::NavBt& nav) {
    const navigation::Path* path = nav.path();
    const auto same = [](const planning::Point2& a, const planning::Point2& b) {
      return a.x == b.x && a.y == b.y;
    };
    if (path == nullptr || (path->size() == last_plan_.size() &&
                            std::equal(path->begin(), path->end(), last_plan_.begin(), same))) {
      return;
    }
    last_plan_ = *path;
    plan_pub_.publish(
        planner_node::toPathMessage(last_plan_, settings_.global_frame, ros::Time::now()));
  }

  void onSimpleGoal(const geometry_msgs::PoseStamped& goal) {
    move_base_msgs::MoveBaseActionGoal action_goal;
    action_goal.header.stamp = ros::Time::now();
    action_goal.goal.target_pose = goal;
    action_goal_pub_.publish(action_goal);
  }

  void onGoal() {
    const auto goal = server_.acceptNewGoal();  // the goal that was active is preempted
    if (settings_.cleaning) {
      ROS_WARN("goal refused: roomba_bt explores and cleans on its own (~unknown)");
      server_.setAborted(move_base_msgs::MoveBaseResult(),
                         "roomba_bt explores and cleans on its own (~unknown): no goals");
      return;
    }
    robot::Pose2D target;
    std::string problem = toGlobal(goal->target_pose, target);
    if (problem.empty() && nav_) {
      problem = goalPlaceProblem(settings_.world, settings_.clearance, target.x, target.y);
    }
    // ~unknown: where the goal lies is for the map to show; a goal far beyond it is refused.
    if (problem.empty() && !nav_ && !to_goal_) {
      problem = "no robot pose yet (tf " + settings_.global_frame + " -> " + settings_.robot_frame +
                "): the map starts where the robot stands";
    }
    if (problem.empty() && to_goal_) {
      try {
        to_goal_->setGoal(target);
      } catch (const std::invalid_argument& e) {
        problem = e.what();
      }
    }
    if (!problem.empty()) {
      cancelGoal();
      goal_open_ = false;
      stop();
      ROS_WARN("goal refused: %s", problem.c_str());
      server_.setAborted(move_base_msgs::MoveBaseResult(), problem);
      return;
    }
    ROS_INFO("goal (%.2f, %.2f, %.2f rad)", target.x, target.y, target.theta);
    if (nav_) nav_->setGoal(target);
    goal_open_ = true;
    ticks_since_feedback_ = 0;
    // Tick at once so that planning starts now, not at the next timer event.
    output_.publish(step());
  }

  void onPreempt() {
    if (server_.isNewGoalAvailable()) return;  // onGoal follows and replaces the goal
    if (!nav_ && !to_goal_) return;            // no goal was taken
    cancelGoal();
    goal_open_ = false;
    stop();
    ROS_INFO("goal canceled");
    server_.setPreempted(move_base_msgs::MoveBaseResult(), "canceled");
  }

  /// "" with `out` the goal in the global frame, or why the goal cannot be used.
  std::string toGlobal(const geometry_msgs::PoseStamped& goal, robot::Pose2D& out) {
    std::string problem = poseProblem(goal.pose);
    if (!problem.empty()) return problem;
    const std::string frame = nodes::tfFrameId(goal.header.frame_id);  // "/map" is "map"
    if (frame.empty()) {
      return "target_pose.header.frame_id: empty (use '" + settings_.global_frame + "')";
    }
    geometry_msgs::Pose pose = goal.pose;
    if (frame != settings_.global_frame) {
      geometry_msgs::TransformStamped t;
      try {
        t = buffer_.lookupTransform(settings_.global_frame, frame, ros::Time(0));
      } catch (const tf2::TransformException& e) {
        return "target_pose.header.frame_id: cannot transform '" + frame + "' to '" +
               settings_.global_frame + "': " + e.what();
      }
      const auto& r = t.transform.rotation;
      const auto& v = t.transform.translation;
      const tf2::Transform transform(tf2::Quaternion(r.x, r.y, r.z, r.w),
                                     tf2::Vector3(v.x, v.y, v.z));
      const auto& q = goal.pose.orientation;
      const tf2::Vector3 p = transform * tf2::Vector3(pose.position.x, pose.position.y, 0);
      const tf2::Quaternion rotated =
          transform.getRotation() * tf2::Quaternion(q.x, q.y, q.z, q.w).normalized();
      pose.position.x = p.x();
      pose.position.y = p.y();
      pose.orientation.x = rotated.x();
      pose.orientation.y = rotated.y();
      pose.orientation.z = rotated.z();
      pose.orientation.w = rotated.w();
    }
    out = toPose2D(pose);
    return "";
  }

  /// dynamic_reconfigure on ~follower (cfg/NavFollower.cfg): FollowPath's limits and
  /// tolerances, from its next tick; refused (and kept) when invalid.
  void startFollowerReconfigure() {
    const navigation::FollowerParams& f = settings_.config.follower;
    NavFollowerConfig in_force;
    in_force.max_linear_speed = f.max_linear_speed;
    in_force.max_angular_speed = f.max_angular_speed;
    in_force.xy_tolerance = f.xy_tolerance;
    in_force.yaw_tolerance = f.yaw_tolerance;
    follower_reconfigure_ = std::make_unique<nodes::Reconfigure<NavFollowerConfig>>(
        ros::NodeHandle("~follower"), in_force, [this](const NavFollowerConfig& c) {
          navigation::FollowerParams next = settings_.config.follower;
          next.max_linear_speed = c.max_linear_speed;
          next.max_angular_speed = c.max_angular_speed;
          next.xy_tolerance = c.xy_tolerance;
          next.yaw_tolerance = c.yaw_tolerance;
          if (nav_) nav_->setFollowerParams(next);
          if (to_goal_) to_goal_->setFollowerParams(next);
          settings_.config.follower = next;
        });
  }

  void stop() { output_.stop(); }

  nodes::CommandOutput& output_;  ///< the node's /cmd_vel
  Settings settings_;
  std::uint32_t seed_;
  std::unique_ptr<navigation::NavBt> nav_;  ///< null with ~unknown
  /// ~unknown: exploring and cleaning, from the first pose tf gives.
  std::unique_ptr<exploration::ExploreClean> explore_;
  /// ~unknown ~known_map with a cleaning tree: cleaning on the known map, from the first pose.
  std::unique_ptr<exploration::CleanKnownMap> known_;
  ros::Publisher known_map_pub_;  ///< ~known_map: the map given, latched
  /// ~unknown with a navigation tree: goals on the map it builds, from the first pose tf gives.
  std::unique_ptr<exploration::NavigateUnknown> to_goal_;
  /// ~unknown with a cleaning tree and no lidar: cleaning by touch, from the first pose tf gives.
  std::unique_ptr<exploration::BumpClean> touch_;
  std::vector<ros::Subscriber> touch_subs_;  ///< its short rangers' scans
  ros::NodeHandle nh_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  MoveBaseServer server_;
  nodes::TfQueue scans_;  ///< ~unknown: scans until tf knows where they were taken
  ros::Subscriber scan_sub_;
  std::unique_ptr<nodes::Reconfigure<NavFollowerConfig>> follower_reconfigure_;
  ros::Publisher plan_pub_, action_goal_pub_, coverage_pub_, report_pub_;
  bool reported_ = false;                 ///< ~coverage_report went out for the cleaning done
  double max_latency_ = 0, slowest_ = 1;  ///< the latency's worst while cleaning
  /// Which coverage plan (its legs' storage and count) and leg ~coverage_path last showed.
  struct CoverageMark {
    const void* legs = nullptr;
    std::size_t count = 0, leg = 0;
    bool operator==(const CoverageMark& o) const {
      return legs == o.legs && count == o.count && leg == o.leg;
    }
  };
  CoverageMark coverage_mark_;
  ros::Subscriber simple_goal_sub_;

  robot::BumperState bumper_;
  bool goal_open_ = false;  ///< the action's current goal awaits its outcome
  int ticks_since_feedback_ = 0;
  navigation::Path last_plan_;
};

double finiteParam(nodes::NodeParams& params, const std::string& name, double fallback,
                   double min) {
  const double value = params.get(name, fallback);
  util::require(std::isfinite(value) && value >= min, "~" + name,
                "finite and >= " + util::show(min), value);
  return value;
}

}  // namespace

std::unique_ptr<behavior::RoombaBehavior> makeNavBehavior(nodes::NodeParams& node_params,
                                                          const behavior::RoombaParams& params,
                                                          std::uint32_t seed,
                                                          const std::string& tree_file,
                                                          nodes::CommandOutput& output) {
  Settings s;
  const std::string world_file =
      node_params.get<std::string>("world_file", nodes::packageConfigFile("roomba_world.yaml"));
  s.world = world::loadWorld(world_file, world::PoseSource::kElsewhere);  // the pose comes from tf
  s.clearance = finiteParam(node_params, "clearance", navigation::kDefaultClearance, 0.0);
  s.global_frame = nodes::tfFrameId(node_params.get<std::string>("global_frame", s.global_frame));
  s.robot_frame = nodes::tfFrameId(
      node_params.get<std::string>("robot_frame", nodes::robotFrame(s.robot_frame)));
  s.unknown = node_params.get("unknown", false);
  const std::string known_map = node_params.get<std::string>("known_map", "");
  if (!known_map.empty() && !s.unknown) {
    throw std::invalid_argument(
        "~known_map is the map a robot that does not know the world is given: set ~unknown "
        "true too (without it roomba_bt plans on ~world_file)");
  }
  const std::string planner =
      node_params.get<std::string>("planner", s.unknown ? "in_process" : "service");
  const std::string service =
      node_params.get<std::string>("plan_path_service", "/rrt_planner/plan_path");

  planning::Problem world = world_planning::roomProblem(s.world);
  world.clearance = s.clearance;
  planning::PlannerOptions options = navigation::navPlannerOptions(world);
  options.seed = seed;
  if (s.unknown) {
    // Plans are made on the map the robot builds: only in process. The world file gives the robot.
    if (planner != "in_process") {
      throw std::invalid_argument(
          "~planner must be 'in_process' with ~unknown (roomba_bt plans on the map it builds), "
          "got '" +
          planner + "'");
    }
    // The tree says what the robot does: a cleaning tree explores, then cleans; a navigation
    // tree takes goals.
    s.cleaning = navigation::usesLeavesOf(tree_file, {coverage::coverageLeaves(nullptr)});
    if (s.cleaning) {
      s.trees = {node_params.get<std::string>("explore_tree_file",
                                              nodes::packageConfigFile("roomba_nav_tree.xml")),
                 tree_file,
                 node_params.get<std::string>(
                     "touch_up_tree_file", nodes::packageConfigFile("roomba_touch_up_tree.xml"))};
    } else {
      s.trees.explore = tree_file;
    }
    s.transform_timeout = node_params.get("transform_timeout", s.transform_timeout);
    util::requireInRange("~transform_timeout", s.transform_timeout, 0.0, 10.0, "s");
    if (!known_map.empty()) {
      try {
        s.known =
            std::make_shared<const exploration::KnownMap>(exploration::loadKnownMap(known_map));
      } catch (const util::InvalidInput& e) {
        throw std::invalid_argument(std::string("~known_map: ") + e.what());
      }
    }
  } else if (planner == "in_process") {
    s.config = navigation::inProcessNavConfig(world, options);
  } else if (planner == "service") {
    const PlanTarget target = planTarget(s.world, s.clearance);
    s.config.planners = [world, options, service, target] {
      return std::make_unique<InProcessPlanner>(world, options, InProcessPlanner::Mode::kThread,
                                                PlanPathClient(service, target, options));
    };
    InProcessPlanner::validate(world, options);
    s.config.known_world = std::make_shared<navigation::PathChecker>(world);
  } else {
    throw std::invalid_argument("~planner must be 'service' or 'in_process', got '" + planner +
                                "'");
  }
  s.config.params = params;
  // roomba_sim publishes a step's pose, then drives one more step with the old command before the
  // command computed from that pose arrives: one tick late (measured at 5x real time: 99.6 % of
  // the commands one step, the rest two to four).
  s.config.pose_latency = node_params.get("pose_latency", 1.0 / params.rate);
  util::requireInRange("~pose_latency", s.config.pose_latency, 0,
                       navigation::PosePredictor::kMaxLatency, "s");
  // The cleaning leaves plan in the same world (their planner is built only if the tree uses them).
  if (!s.unknown) {
    s.config.more_leaves.push_back(
        coverage::coverageLeaves(s.world, coverage::cleaningOptions(s.world)));
  }
  navigation::FollowerParams& f = s.config.follower;
  f.rate = params.rate;
  using L =
      navigation::FollowerLimits;  // also cfg/NavFollower.cfg's minimum; validate() the maxima
  f.max_linear_speed = finiteParam(node_params, "max_linear_speed", f.max_linear_speed, L::kMin);
  f.max_angular_speed = finiteParam(node_params, "max_angular_speed", f.max_angular_speed, L::kMin);
  f.xy_tolerance = finiteParam(node_params, "xy_tolerance", f.xy_tolerance, L::kMin);
  f.yaw_tolerance = finiteParam(node_params, "yaw_tolerance", f.yaw_tolerance, L::kMin);
  navigation::validate(f);
  node_params.expect("follower/");  // the follower's dynamic_reconfigure (NavFollower.cfg)
  // Which of the planner's worlds the plans are asked in: a planner on another world answers
  // "start ... is outside the bounds" to every goal, so the user is told what it must have.
  if (s.unknown && !s.cleaning) {
    ROS_INFO(
        "roomba_bt: navigation in a home it has never seen (~unknown): scans on %s, the robot "
        "of %s, tree %s",
        ros::NodeHandle().resolveName("scan").c_str(), world_file.c_str(), tree_file.c_str());
    return std::make_unique<NavBehavior>(params, seed, tree_file, std::move(s), output);
  }
  if (s.unknown && s.known && s.cleaning) {
    ROS_INFO(
        "roomba_bt: cleaning with the map it was given (~known_map %s, its walls trusted) and "
        "scans on %s, the robot of %s, tree %s",
        s.known->file.c_str(), ros::NodeHandle().resolveName("scan").c_str(), world_file.c_str(),
        s.trees.clean.c_str());
    return std::make_unique<NavBehavior>(params, seed, tree_file, std::move(s), output);
  }
  if (s.unknown && exploration::cleansByTouch(s.world.robot())) {
    std::string topics;
    for (const sensors::RangeSensorSpec& sensor : s.world.robot().sensors) {
      topics += (topics.empty() ? "" : ", ") + ros::NodeHandle().resolveName(sensor.name);
    }
    ROS_INFO(
        "roomba_bt: cleaning a home it has never seen by touch (~unknown, no sensor of the robot "
        "of %s reaches %.0f m): the bumper%s%s, online boustrophedon",
        world_file.c_str(), exploration::kLongRange, topics.empty() ? " alone" : " and ",
        topics.c_str());
    return std::make_unique<NavBehavior>(params, seed, tree_file, std::move(s), output);
  }
  if (s.unknown) {
    ROS_INFO(
        "roomba_bt: exploring and cleaning a home it has never seen (~unknown): scans on "
        "%s, the robot of %s, trees %s then %s",
        ros::NodeHandle().resolveName("scan").c_str(), world_file.c_str(), s.trees.explore.c_str(),
        s.trees.clean.c_str());
    return std::make_unique<NavBehavior>(params, seed, tree_file, std::move(s), output);
  }
  std::string asks;
  if (planner == "service") {
    asks = planTarget(s.world, s.clearance).scenario == "map"
               ? " (" + service + ", scenario map: the map on the planner's ~map_topic)"
               : " (" + service + ", scenario room: the planner's ~world_file must be " +
                     world_file + ")";
  }
  ROS_INFO("roomba_bt: navigation in %s, planner %s%s", world_file.c_str(), planner.c_str(),
           asks.c_str());
  return std::make_unique<NavBehavior>(params, seed, tree_file, std::move(s), output);
}

}  // namespace roomba_rrt::nav_node
