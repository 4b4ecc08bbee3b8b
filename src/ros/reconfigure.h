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
#include <vector>

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <boost/thread/recursive_mutex.hpp>

namespace roomba_rrt::nodes {

/// The names of `Config`'s parameters (the server writes them into its namespace).
template <class Config>
std::vector<std::string> parameterNames() {
  std::vector<std::string> names;
  for (const auto& description : Config::__getParamDescriptions__()) {
    names.push_back(description->name);
  }
  return names;
}

template <class Config>
class Reconfigure {
 public:
  /// Applies a requested configuration; throws std::exception (e.g. util::InvalidInput naming
  /// the field) to refuse it.
  using Apply = std::function<void(const Config&)>;

  /// Serves the parameters of `Config` on `nh`'s namespace (the node's private one, or
  /// ~follower), starting from `in_force`.
  Reconfigure(const ros::NodeHandle& nh, const Config& in_force, Apply apply)
      : nh_(nh),
        fresh_(absent(nh)),
        server_(mutex_, nh),
        in_force_(in_force),
        apply_(std::move(apply)) {
    server_.updateConfig(in_force_);
    server_.setCallback([this](Config& requested, std::uint32_t) { onRequest(requested); });
  }

  /// The server writes every parameter into its namespace; those that were not set before are
  /// deleted again, so that none is left on the master to override the next start's values.
  ~Reconfigure() {
    for (const std::string& name : fresh_) nh_.deleteParam(name);
  }
  Reconfigure(const Reconfigure&) = delete;
  Reconfigure& operator=(const Reconfigure&) = delete;

 private:
  static std::vector<std::string> absent(const ros::NodeHandle& nh) {
    std::vector<std::string> names;
    for (const std::string& name : parameterNames<Config>()) {
      if (!nh.hasParam(name)) names.push_back(name);
    }
    return names;
  }

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

  ros::NodeHandle nh_;
  std::vector<std::string> fresh_;  ///< not set before the server wrote them
  boost::recursive_mutex mutex_;    ///< given to the server: updateConfig() takes it
  dynamic_reconfigure::Server<Config> server_;
  Config in_force_;
  Apply apply_;
  bool started_ = false;
};

}  // namespace roomba_rrt::nodes
