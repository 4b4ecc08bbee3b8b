#include "behavior_node.h"

#include "master_watch.h"
#include "message_parts.h"
#include "reconfigure.h"
#include "shutdown_grace.h"
#include "tree_watch.h"

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <roomba_rrt/Bumper.h>
#include <roomba_rrt/RoombaBehaviorConfig.h>
#include <ros/package.h>
#include <std_msgs/String.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <sstream>
#include <utility>

namespace roomba_rrt::nodes {
namespace {

/// The node: one behaviour, its inputs and outputs.
class BehaviorNode {
 public:
  BehaviorNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, NodeParams& node_params,
               CommandOutput& output, std::unique_ptr<behavior::RoombaBehavior> behavior,
               double rate, double bumper_timeout, const std::string& tree_nodes_model)
      : output_(output),
        behavior_(std::move(behavior)),
        period_(1.0 / rate),
        max_catch_up_(std::max(1, static_cast<int>(rate))),
        bumper_timeout_(bumper_timeout),
        base_frame_(node_params.get<std::string>("base_frame", robotFrame("base_link"))) {
    state_pub_ = pnh.advertise<std_msgs::String>("state", 10, /*latch=*/true);
    marker_pub_ = pnh.advertise<visualization_msgs::Marker>("state_marker", 1, /*latch=*/true);
    bumper_sub_ = nh.subscribe("bumper", 1, &BehaviorNode::onBumper, this);
    odom_sub_ = nh.subscribe("odom", 1, &BehaviorNode::onOdom, this);
    timer_ = nh.createTimer(period_, &BehaviorNode::onTimer, this);
    startReconfigure(pnh);
    if (bt::Tree* tree = behavior_->behaviorTree()) {
      watch_ = std::make_unique<TreeWatch>(pnh, node_params, *tree,
                                           treeId(node_params.get<std::string>("tree_file", "")),
                                           tree_nodes_model);
    }
    for (const std::string& name : parameterNames<RoombaBehaviorConfig>()) node_params.expect(name);
  }

 private:
  /// The ID of the tree `tree_file` runs ("MainTree" when it cannot be read).
  static std::string treeId(const std::string& tree_file) {
    std::ifstream in(tree_file);
    std::stringstream text;
    text << in.rdbuf();
    return bt::mainTreeId(text.str());
  }

  /// dynamic_reconfigure (cfg/RoombaBehavior.cfg): the lab's constants, used by every motion
  /// that starts after the change (RoombaBehavior::setParams); refused (and kept) when invalid.
  void startReconfigure(const ros::NodeHandle& pnh) {
    using P = behavior::RoombaParams;
    using C = RoombaBehaviorConfig;
    // Every constant of the .cfg and where it lives in RoombaParams (~rate is not reconfigurable).
    static constexpr std::pair<double P::*, double C::*> kFields[] = {
        {&P::move_forward_time, &C::move_forward_time},
        {&P::move_in_spiral_time, &C::move_in_spiral_time},
        {&P::go_back_time, &C::go_back_time},
        {&P::forward_speed, &C::forward_speed},
        {&P::backward_speed, &C::backward_speed},
        {&P::angular_speed, &C::angular_speed},
        {&P::initial_radius_spiral, &C::initial_radius_spiral},
        {&P::spiral_factor, &C::spiral_factor}};
    C in_force;
    for (const auto& [param, config] : kFields) in_force.*config = behavior_->params().*param;
    reconfigure_ = std::make_unique<Reconfigure<C>>(pnh, in_force, [this](const C& requested) {
      P next = behavior_->params();
      for (const auto& [param, config] : kFields) next.*param = requested.*config;
      behavior_->setParams(next);
    });
  }

  void onBumper(const roomba_rrt::Bumper& msg) {
    bumper_.pressed = msg.pressed;
    bumper_.left = msg.left;
    bumper_.right = msg.right;
    last_bumper_ = ros::Time::now();
    have_bumper_ = true;
  }

  void onOdom(const nav_msgs::Odometry& msg) {
    const auto& p = msg.pose.pose.position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      ROS_WARN_THROTTLE(5.0, "ignoring /odom with a non-finite position");
      return;
    }
    x_ = p.x;
    y_ = p.y;
    odom_frame_ = msg.header.frame_id;
  }

  void onTimer(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    if (!have_bumper_ || (now - last_bumper_).toSec() > bumper_timeout_) {
      // A behaviour must not drive blind: stop until the bumper speaks again.
      output_.stop();
      ROS_WARN_THROTTLE(5.0, "no /bumper for more than %.2f s: commanding zero velocity",
                        bumper_timeout_);
      next_tick_ = ros::Time();  // no catching up on the blind time
      return;
    }
    // The behaviour measures time in ticks, so it must tick once per period of ROS time. roscpp
    // skips timer events it is late for (a loaded machine, a fast /clock): tick for those too,
    // with the latest bumper, so that e.g. GoBack still lasts 0.5 s of robot time.
    // Start afresh at the first tick, after blind time, or when the clock went back.
    if (next_tick_.isZero() || now + period_ * 2.0 < next_tick_) next_tick_ = now;
    const ros::Time due = now + period_ * 0.5;
    int ticks = 0;
    robot::Velocity cmd;
    while (next_tick_ <= due && ticks < max_catch_up_) {
      cmd = behavior_->tick(bumper_);
      if (watch_) watch_->afterTick(x_, y_, odom_frame_);
      next_tick_ += period_;
      ++ticks;
      const std::string& state = behavior_->stateName();
      if (state != last_state_) {
        ROS_DEBUG("%s at (%.2f, %.2f)", state.c_str(), x_, y_);
        last_state_ = state;
        publishState(state);
      }
    }
    if (ticks == 0) return;                                  // an early event: nothing is due yet
    if (ticks == max_catch_up_) next_tick_ = now + period_;  // too far behind: do not chase
    output_.publish(cmd);
  }

  void publishState(const std::string& state) {
    std_msgs::String msg;
    msg.data = state;
    state_pub_.publish(msg);

    // Stamp 0: the robot's latest transform, every frame (frame_locked), so the text follows it.
    // Black: readable on the robot's blue, on the floor not yet cleaned and on the near-white
    // floor the robot has cleaned (white text vanished there).
    visualization_msgs::Marker marker =
        makeMarker(base_frame_, ros::Time(0), ros::this_node::getName(), 0,
                   visualization_msgs::Marker::TEXT_VIEW_FACING, color(0.0f, 0.0f, 0.0f));
    marker.frame_locked = true;
    marker.pose.position.z = 0.45;  // a little above the robot
    marker.scale.z = 0.2;           // text height, m
    marker.text = state;
    marker_pub_.publish(marker);
  }

  CommandOutput& output_;
  std::unique_ptr<behavior::RoombaBehavior> behavior_;
  std::unique_ptr<Reconfigure<RoombaBehaviorConfig>> reconfigure_;
  std::unique_ptr<TreeWatch> watch_;  ///< a behavior tree's monitors (none for the FSM)
  ros::Duration period_;
  int max_catch_up_;  ///< at most one second of ticks per timer event
  double bumper_timeout_;
  std::string base_frame_;  ///< ~base_frame: the frame the state text hangs on
  ros::Publisher state_pub_, marker_pub_;
  ros::Subscriber bumper_sub_, odom_sub_;
  ros::Timer timer_;

  robot::BumperState bumper_;
  ros::Time last_bumper_;
  ros::Time next_tick_;  ///< ROS time of the next tick due (zero: start afresh)
  bool have_bumper_ = false;
  double x_ = 0, y_ = 0;
  std::string odom_frame_;  ///< /odom's frame: the tree markers are drawn in it
  std::string last_state_;
};

}  // namespace

CommandOutput::CommandOutput(ros::NodeHandle& nh)
    : pub_(nh.advertise<geometry_msgs::Twist>("cmd_vel", 1)) {}

void CommandOutput::publish(const robot::Velocity& cmd) {
  geometry_msgs::Twist twist;
  twist.linear.x = std::isfinite(cmd.v) ? cmd.v : 0.0;
  twist.angular.z = std::isfinite(cmd.w) ? cmd.w : 0.0;
  pub_.publish(twist);
}

std::string robotFrame(const std::string& frame) {
  std::string ns = ros::this_node::getNamespace();
  while (!ns.empty() && ns.front() == '/') ns.erase(0, 1);
  return ns.empty() ? frame : ns + "/" + frame;
}

int runBehaviorNode(int argc, char** argv, const std::string& node_name,
                    const BehaviorMaker& make_behavior, const std::string& tree_nodes_model) {
  ros::init(argc, argv, node_name);
  stopOnSigterm();
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  MasterWatch master_watch;
  try {
    NodeParams node_params(pnh);
    const std::string config_file =
        node_params.get<std::string>("config_file", packageConfigFile("roomba_behavior.yaml"));
    behavior::RoombaParams params = behavior::loadRoombaParams(config_file);
    params.rate = node_params.get("rate", params.rate);
    const int seed = node_params.get("seed", 1);
    const double bumper_timeout = node_params.get("bumper_timeout", 0.5);
    if (!(bumper_timeout > 0 && bumper_timeout <= 1e6)) {
      throw std::invalid_argument("~bumper_timeout must be in (0, 1e6] s");
    }
    if (seed < 0) throw std::invalid_argument("~seed must be >= 0, got " + std::to_string(seed));
    try {
      behavior::validate(params);  // ~rate may have changed
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("~") + e.what());
    }

    CommandOutput output(nh);
    BehaviorNode node(nh, pnh, node_params, output,
                      make_behavior(node_params, params, static_cast<std::uint32_t>(seed), output),
                      params.rate, bumper_timeout, tree_nodes_model);
    node_params.warnUnknown();
    ROS_INFO("%s: ticking at %.1f Hz (seed %d, parameters from %s)", node_name.c_str(), params.rate,
             seed, config_file.c_str());
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("%s: %s", node_name.c_str(), e.what());
    return 1;
  }
  return master_watch.exitCode();
}

}  // namespace roomba_rrt::nodes
