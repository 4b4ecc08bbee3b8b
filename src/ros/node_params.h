// A node's private parameters, read one way by every node of the package: a value of the wrong
// type is an error naming the parameter (never silently the default), a private parameter that no
// part of the node reads is warned about (with the nearest known name: a typo), and the values in
// force are written back so that `rosparam get` shows them while the node runs.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>

namespace roomba_rrt::nodes {

class NodeParams {
 public:
  /// The parameters of `private_nh`'s namespace (the node's ~).
  explicit NodeParams(const ros::NodeHandle& private_nh);
  /// Deletes the values it wrote back that were not set when the node started, so that a value
  /// in force (e.g. a rate read from a YAML file) is not left pinned on the master to override
  /// the file at the next start. Best effort: the master may be gone.
  ~NodeParams();
  NodeParams(const NodeParams&) = delete;
  NodeParams& operator=(const NodeParams&) = delete;

  /// ~name, or `fallback` when it is not set; written back either way (`write_back` false: not).
  /// std::invalid_argument "~name: must be <type>, got <value>" when it has another type.
  /// T: bool, int, double, std::string or std::vector<double>.
  template <class T>
  T get(const std::string& name, const T& fallback, bool write_back = true);

  /// Whether ~name is set.
  bool has(const std::string& name) const { return nh_.hasParam(name); }

  /// Marks ~name as read by another part of the node (dynamic_reconfigure's server, a world
  /// file's overrides); a name ending in '/' marks a whole namespace.
  void expect(const std::string& name) { known_.insert(name); }

  /// ROS_WARN for every private parameter no part of the node reads: "~real_time_factr is not a
  /// parameter of this node (did you mean ~real_time_factor?); it is ignored".
  void warnUnknown() const;

  /// The private parameters that nothing reads (what warnUnknown() warns about).
  std::vector<std::string> unknown() const;

 private:
  template <class T>
  void writeBack(const std::string& name, const T& value, bool was_set);

  ros::NodeHandle nh_;
  std::set<std::string> known_;
  std::vector<std::string> written_;  ///< written back, not set at start: deleted at exit
};

/// The path of a file in the package's config/ folder, where the nodes' default files are
/// (ros::package::getPath; the source tree's config/ when the package is not on
/// ROS_PACKAGE_PATH).
std::string packageConfigFile(const std::string& file_name);

/// When an argument is --help or -h: prints "Usage: rosrun roomba_rrt <node> [_param:=value
/// ...]", `what` and where its parameters are documented, and returns true (the node then exits
/// 0, before ros::init, which would wait for a master).
bool printedHelp(int argc, char** argv, const std::string& node, const std::string& what);

}  // namespace roomba_rrt::nodes
