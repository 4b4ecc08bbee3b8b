// dynamic_reconfigure for the package's nodes: a server whose values start as the ones in force
// (the YAML files and _param:=, not the .cfg's defaults) and whose callback applies a change or
// refuses it. dynamic_reconfigure itself clamps a value to the .cfg's range, and the .cfg ranges
// are the ones the nodes validate (reconfigure_ranges_test), so what is left to refuse is an open
// end (a speed of exactly 0) or a rule between parameters (v·step below the robot's radius): the
// node then keeps the values in force and says why, and dynparam get shows them.
#pragma once

#include <exception>
#include <functional>
#include <string>

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <boost/thread/recursive_mutex.hpp>

namespace roomba_rrt::nodes {

template <class Config>
class Reconfigure {
 public:
  /// Applies a requested configuration; throws std::exception (e.g. util::InvalidInput naming
  /// the field) to refuse it.
  using Apply = std::function<void(const Config&)>;

  /// Serves the parameters of `Config` on `nh`'s namespace (the node's private one, or
  /// ~follower), starting from `in_force`.
  Reconfigure(const ros::NodeHandle& nh, const Config& in_force, Apply apply)
      : server_(mutex_, nh), in_force_(in_force), apply_(std::move(apply)) {
    server_.updateConfig(in_force_);
    server_.setCallback([this](Config& requested, std::uint32_t) { onRequest(requested); });
  }

 private:
  void onRequest(Config& requested) {
    if (!started_) {  // setCallback's first call hands back the values in force
      started_ = true;
      return;
    }
    try {
      apply_(requested);
      in_force_ = requested;
    } catch (const std::exception& e) {
      ROS_WARN("%s: dynamic_reconfigure: refused (%s); keeping the values in force",
               ros::this_node::getName().c_str(), e.what());
      requested = in_force_;  // what the server publishes and dynparam get shows
    }
  }

  boost::recursive_mutex mutex_;  // given to the server: updateConfig() takes it
  dynamic_reconfigure::Server<Config> server_;
  Config in_force_;
  Apply apply_;
  bool started_ = false;
};

}  // namespace roomba_rrt::nodes
