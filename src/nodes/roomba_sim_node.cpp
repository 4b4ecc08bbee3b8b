// roomba_sim: the simulated Roombas as a ROS node — a thin adapter around
// roomba_rrt::sim::MultiRobotSimulator.
//
// One unnamed robot (today's world files): subscribes /cmd_vel; publishes /odom, /bumper, tf
// odom→base_link (+ static map→odom, the identity: odometry is perfect and in room coordinates).
// Named robots (`robots:` in the world file): the same per robot under its name — /<name>/cmd_vel,
// /<name>/odom, /<name>/bumper, tf <name>/odom→<name>/base_link, static map→<name>/odom,
// ~<name>/coverage — each with its own command timeout. Always one /clock (when /use_sim_time is
// true), ~markers (every robot, with its name), ~coverage and ~coverage_map (the union); service
// ~reset. Parameters: see README.md, "The simulated Roomba".
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <roomba_rrt/Bumper.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float32.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "master_watch.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/sim/world.h"

namespace roomba_rrt {
namespace {

using sim::World;
using Clock = std::chrono::steady_clock;

constexpr double kMarkerPeriod = 0.1;        // wall s between ~markers (10 Hz)
constexpr double kCoveragePeriod = 0.5;      // wall s between ~coverage (2 Hz)
constexpr double kCoverageMapPeriod = 0.5;   // wall s between ~coverage_map (2 Hz)
constexpr double kTrailSpacing = 0.02;       // m between trail points
constexpr std::size_t kTrailLength = 5000;   // points kept (100 m of path)
constexpr std::uint32_t kStateQueue = 1000;  // /odom and /bumper publisher queues
constexpr double kMaxLag = 0.25;             // wall s behind schedule before the schedule resets
constexpr std::chrono::duration<double> kMaxSleep(0.05);  // longest uninterrupted sleep, wall s
constexpr double kRobotHeight = 0.09, kFurnitureHeight = 0.4, kWallHeight = 0.3;
constexpr double kWallThickness = 0.05;

/// Reads the world file, then lets every scalar be overridden by a private parameter of the same
/// path (~real_time_factor, ~initial_pose/x, ~robot/radius, ...). Nothing is written back: a
/// value pinned on the master would silently override the file on the next start.
/// Throws std::invalid_argument naming the bad parameter.
World loadWorldParameters(const ros::NodeHandle& pnh) {
  const std::string default_file =
      ros::package::getPath("roomba_rrt") + "/config/roomba_world.yaml";
  World world = sim::loadWorld(pnh.param<std::string>("world_file", default_file));
  const std::vector<std::pair<const char*, double*>> overrides = {
      {"room/width", &world.width},
      {"room/height", &world.height},
      {"robot/radius", &world.robot_radius},
      {"robot/max_linear_speed", &world.max_linear_speed},
      {"robot/max_angular_speed", &world.max_angular_speed},
      {"initial_pose/x", &world.initial_pose.x},
      {"initial_pose/y", &world.initial_pose.y},
      {"initial_pose/theta", &world.initial_pose.theta},
      {"step", &world.step},
      {"coverage_cell_size", &world.coverage_cell_size},
      {"command_timeout", &world.command_timeout},
      {"real_time_factor", &world.real_time_factor},
  };
  for (const auto& [name, value] : overrides) {
    if (pnh.hasParam(name) && !pnh.getParam(name, *value)) {
      throw std::invalid_argument(std::string("~") + name + " must be a number");
    }
  }
  if (!world.robots.empty() && pnh.hasParam("initial_pose")) {
    throw std::invalid_argument("~initial_pose cannot be used with the world file's robots");
  }
  sim::validate(world);
  return world;
}

geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

struct Rgb {
  double r, g, b;
};
const Rgb kWallColour{0.55, 0.55, 0.55}, kFurnitureColour{0.55, 0.35, 0.2},
    kTrailColour{0.1, 0.8, 0.3}, kRobotColour{0.2, 0.6, 0.9}, kPressedColour{0.9, 0.2, 0.2};

visualization_msgs::Marker makeMarker(const std::string& ns, int id, int type, Rgb colour) {
  visualization_msgs::Marker m;
  m.header.frame_id = "map";
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color.r = colour.r;
  m.color.g = colour.g;
  m.color.b = colour.b;
  m.color.a = 1.0;
  return m;
}

/// A box marker over [x0, x1] × [y0, y1], `height` tall, standing on the floor.
visualization_msgs::Marker makeBox(const std::string& ns, int id, double x0, double y0, double x1,
                                   double y1, double height, Rgb colour) {
  auto m = makeMarker(ns, id, visualization_msgs::Marker::CUBE, colour);
  m.pose.position.x = 0.5 * (x0 + x1);
  m.pose.position.y = 0.5 * (y0 + y1);
  m.pose.position.z = 0.5 * height;
  m.scale.x = x1 - x0;
  m.scale.y = y1 - y0;
  m.scale.z = height;
  return m;
}

class RoombaSimNode {
 public:
  RoombaSimNode(const World& world, bool use_sim_time)
      : pnh_("~"), sim_(world), use_sim_time_(use_sim_time), robots_(sim_.size()) {
    if (use_sim_time_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("clock", 10);
    markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    coverage_pub_ = pnh_.advertise<std_msgs::Float32>("coverage", 1, true);
    coverage_map_pub_ = pnh_.advertise<nav_msgs::OccupancyGrid>("coverage_map", 1, true);
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      RobotIo& io = robots_[i];
      const std::string& name = sim_.spec(i).name;
      io.prefix = name.empty() ? "" : name + "/";  // topics and frames of a named robot
      io.odom_frame = io.prefix + "odom";
      io.base_frame = io.prefix + "base_link";
      // Deep queues: at real_time_factor 50 these go out 3000 times per second, and a subscriber
      // that is descheduled for a moment must not lose any.
      io.odom_pub = nh_.advertise<nav_msgs::Odometry>(io.prefix + "odom", kStateQueue);
      io.bumper_pub = nh_.advertise<roomba_rrt::Bumper>(io.prefix + "bumper", kStateQueue);
      if (!name.empty()) {
        io.coverage_pub = pnh_.advertise<std_msgs::Float32>(io.prefix + "coverage", 1, true);
      }
      io.cmd_sub = nh_.subscribe<geometry_msgs::Twist>(
          io.prefix + "cmd_vel", 10,
          [this, i](const geometry_msgs::Twist::ConstPtr& msg) { onCommand(i, *msg); },
          ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
      io.trail = makeMarker("trail", static_cast<int>(i), visualization_msgs::Marker::LINE_STRIP,
                            kTrailColour);
      io.trail.scale.x = 0.02;  // line width, m
    }
    reset_srv_ = pnh_.advertiseService("reset", &RoombaSimNode::onReset, this);
    publishStaticTransforms();
    wall_markers_ = worldMarkers();
  }

  /// The fixed-step loop: sense contact, publish the state, apply the latest command, keep pace
  /// with the wall clock (× real_time_factor when the simulator owns /clock).
  void run() {
    const World& world = sim_.world();
    const double factor = use_sim_time_ ? world.real_time_factor : 1.0;
    const auto wall_step = std::chrono::duration<double>(world.step / factor);
    auto next_step = Clock::now();
    while (ros::ok()) {
      ros::spinOnce();
      const ros::Time now = currentTime();
      sim_.senseContact();
      publishState(now);
      for (std::size_t i = 0; i < robots_.size(); ++i) commands_[i] = activeCommand(i, now);
      sim_.move(commands_);
      ++steps_;
      publishSlowTopics(now);

      next_step += std::chrono::duration_cast<Clock::duration>(wall_step);
      const auto wall_now = Clock::now();
      if (wall_now < next_step) {
        waitUntil(next_step);
      } else if (wall_now - next_step > std::chrono::duration<double>(kMaxLag)) {
        ROS_WARN_STREAM_THROTTLE(5.0, "roomba_sim cannot keep real_time_factor "
                                          << factor << "; simulated time is running slower");
        next_step = wall_now;  // drop the lag instead of racing to catch up
      }
    }
  }

 private:
  /// Sleeps until `deadline`, but in slices of at most kMaxSleep so that a slow real-time factor
  /// (one step every 166 s at 1e-4) still answers ~reset and stops promptly on Ctrl-C.
  void waitUntil(Clock::time_point deadline) {
    const auto slice = std::chrono::duration_cast<Clock::duration>(kMaxSleep);
    for (auto now = Clock::now(); now < deadline && ros::ok(); now = Clock::now()) {
      std::this_thread::sleep_until(std::min(deadline, now + slice));
      if (deadline - Clock::now() > slice / 2) ros::spinOnce();  // a long wait: serve callbacks
    }
  }

  /// The simulator owns time when /use_sim_time is true: steps × step since start.
  ros::Time currentTime() const {
    return use_sim_time_ ? ros::Time(steps_ * sim_.world().step) : ros::Time::now();
  }

  void onCommand(std::size_t robot, const geometry_msgs::Twist& msg) {
    if (!std::isfinite(msg.linear.x) || !std::isfinite(msg.angular.z)) {
      ROS_WARN_THROTTLE(1.0,
                        "roomba_sim: rejecting /%scmd_vel with a NaN or infinite component "
                        "(linear.x=%g, angular.z=%g)",
                        robots_[robot].prefix.c_str(), msg.linear.x, msg.angular.z);
      return;
    }
    robots_[robot].command = {msg.linear.x, msg.angular.z};  // clamped by the simulator
    robots_[robot].command_time = currentTime();
  }

  /// Robot i's latest command, or a stop when it is older than command_timeout.
  sim::Velocity activeCommand(std::size_t robot, const ros::Time& now) const {
    const RobotIo& io = robots_[robot];
    if (!io.command_time || (now - *io.command_time).toSec() > sim_.world().command_timeout) {
      return {};
    }
    return io.command;
  }

  bool onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    sim_.reset();
    for (RobotIo& io : robots_) {
      io.command = {};
      io.command_time.reset();
      io.trail.points.clear();
    }
    ROS_INFO("roomba_sim: reset to the initial pose, coverage cleared");
    return true;
  }

  /// map → odom (or map → <name>/odom for every named robot): the identity.
  void publishStaticTransforms() {
    std::vector<geometry_msgs::TransformStamped> transforms;
    for (const RobotIo& io : robots_) {
      geometry_msgs::TransformStamped map_to_odom;
      map_to_odom.header.stamp = ros::Time::now();
      map_to_odom.header.frame_id = "map";
      map_to_odom.child_frame_id = io.prefix + "odom";
      map_to_odom.transform.rotation.w = 1.0;
      transforms.push_back(map_to_odom);
    }
    static_tf_.sendTransform(transforms);
  }

  /// /clock, then every robot's odometry, bumper and odom → base_link (one tf message for all).
  void publishState(const ros::Time& stamp) {
    if (use_sim_time_) {
      rosgraph_msgs::Clock clock;
      clock.clock = stamp;
      clock_pub_.publish(clock);
    }
    transforms_.resize(robots_.size());
    for (std::size_t i = 0; i < robots_.size(); ++i) publishRobotState(i, stamp, transforms_[i]);
    tf_.sendTransform(transforms_);
  }

  void publishRobotState(std::size_t i, const ros::Time& stamp,
                         geometry_msgs::TransformStamped& tf) {
    const RobotIo& io = robots_[i];
    const sim::Pose2D& pose = sim_.pose(i);
    const sim::Velocity applied = sim_.lastCommand(i);
    const sim::BumperState& bumper = sim_.bumper(i);
    nav_msgs::Odometry odom;
    odom.header.stamp = stamp;
    odom.header.frame_id = io.odom_frame;
    odom.child_frame_id = io.base_frame;
    odom.pose.pose.position.x = pose.x;
    odom.pose.pose.position.y = pose.y;
    odom.pose.pose.orientation = yawToQuaternion(pose.theta);
    odom.twist.twist.linear.x = applied.v;
    odom.twist.twist.angular.z = applied.w;
    io.odom_pub.publish(odom);

    roomba_rrt::Bumper bumper_msg;
    bumper_msg.header.stamp = stamp;
    bumper_msg.header.frame_id = odom.child_frame_id;
    bumper_msg.pressed = bumper.pressed;
    bumper_msg.left = bumper.left;
    bumper_msg.right = bumper.right;
    io.bumper_pub.publish(bumper_msg);

    tf.header = odom.header;
    tf.child_frame_id = odom.child_frame_id;
    tf.transform.translation.x = pose.x;
    tf.transform.translation.y = pose.y;
    tf.transform.rotation = odom.pose.pose.orientation;
  }

  /// Markers, coverage and the coverage map, a few times per wall-clock second.
  void publishSlowTopics(const ros::Time& stamp) {
    for (std::size_t i = 0; i < robots_.size(); ++i) extendTrail(i);
    const ros::WallTime wall = ros::WallTime::now();
    if ((wall - last_markers_).toSec() >= kMarkerPeriod) {
      last_markers_ = wall;
      if (markers_pub_.getNumSubscribers() > 0) markers_pub_.publish(robotMarkers(stamp));
    }
    if ((wall - last_coverage_).toSec() >= kCoveragePeriod) {
      last_coverage_ = wall;
      std_msgs::Float32 coverage;
      coverage.data = static_cast<float>(sim_.unionCoverage());
      coverage_pub_.publish(coverage);
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        if (!robots_[i].coverage_pub) continue;
        coverage.data = static_cast<float>(sim_.coverage(i));
        robots_[i].coverage_pub.publish(coverage);
      }
    }
    if ((wall - last_coverage_map_).toSec() >= kCoverageMapPeriod) {
      last_coverage_map_ = wall;
      if (coverage_map_pub_.getNumSubscribers() > 0) coverage_map_pub_.publish(coverageMap(stamp));
    }
  }

  void extendTrail(std::size_t i) {
    const sim::Pose2D& pose = sim_.pose(i);
    std::vector<geometry_msgs::Point>& points = robots_[i].trail.points;
    if (!points.empty()) {
      const auto& last = points.back();
      if (std::hypot(pose.x - last.x, pose.y - last.y) < kTrailSpacing) return;
    }
    if (points.size() >= kTrailLength) {
      points.erase(points.begin(), points.begin() + kTrailLength / 2);
    }
    geometry_msgs::Point p;
    p.x = pose.x;
    p.y = pose.y;
    p.z = 0.01;
    points.push_back(p);
  }

  /// Walls and furniture: they never change, built once.
  std::vector<visualization_msgs::Marker> worldMarkers() const {
    using visualization_msgs::Marker;
    const World& w = sim_.world();
    const double t = kWallThickness;
    std::vector<Marker> markers = {
        makeBox("walls", 0, -t, -t, 0, w.height + t, kWallHeight, kWallColour),
        makeBox("walls", 1, w.width, -t, w.width + t, w.height + t, kWallHeight, kWallColour),
        makeBox("walls", 2, 0, -t, w.width, 0, kWallHeight, kWallColour),
        makeBox("walls", 3, 0, w.height, w.width, w.height + t, kWallHeight, kWallColour),
    };
    int id = 0;
    for (const sim::Circle& c : w.circles) {
      auto m = makeMarker("furniture", id++, Marker::CYLINDER, kFurnitureColour);
      m.pose.position.x = c.center.x;
      m.pose.position.y = c.center.y;
      m.pose.position.z = 0.5 * kFurnitureHeight;
      m.scale.x = m.scale.y = 2 * c.radius;
      m.scale.z = kFurnitureHeight;
      markers.push_back(m);
    }
    for (const sim::Rectangle& b : w.rectangles) {
      markers.push_back(makeBox("furniture", id++, b.min_x, b.min_y, b.max_x, b.max_y,
                                kFurnitureHeight, kFurnitureColour));
    }
    return markers;
  }

  visualization_msgs::MarkerArray robotMarkers(const ros::Time& stamp) const {
    visualization_msgs::MarkerArray array;
    array.markers = wall_markers_;
    for (std::size_t i = 0; i < robots_.size(); ++i) addRobotMarkers(i, array);
    for (auto& m : array.markers) m.header.stamp = stamp;
    return array;
  }

  /// Robot i's disc (red while its bumper is pressed), heading, trail and, when named, its name.
  void addRobotMarkers(std::size_t i, visualization_msgs::MarkerArray& array) const {
    using visualization_msgs::Marker;
    const sim::Pose2D& pose = sim_.pose(i);
    const double r = sim_.spec(i).radius;
    const int id = static_cast<int>(i);
    const bool pressed = sim_.bumper(i).pressed;
    auto robot = makeMarker("robot", id, Marker::CYLINDER, pressed ? kPressedColour : kRobotColour);
    robot.pose.position.x = pose.x;
    robot.pose.position.y = pose.y;
    robot.pose.position.z = 0.5 * kRobotHeight;
    robot.scale.x = robot.scale.y = 2 * r;
    robot.scale.z = kRobotHeight;
    array.markers.push_back(robot);

    auto heading = makeMarker("heading", id, Marker::ARROW, Rgb{1.0, 1.0, 1.0});
    heading.pose.position.x = pose.x;
    heading.pose.position.y = pose.y;
    heading.pose.position.z = kRobotHeight + 0.01;
    heading.pose.orientation = yawToQuaternion(pose.theta);
    heading.scale.x = r;
    heading.scale.y = 0.04;
    heading.scale.z = 0.04;
    array.markers.push_back(heading);

    if (robots_[i].trail.points.size() >= 2) array.markers.push_back(robots_[i].trail);
    if (!sim_.spec(i).name.empty()) {
      auto name = makeMarker("names", id, Marker::TEXT_VIEW_FACING, Rgb{0.1, 0.1, 0.1});
      name.text = sim_.spec(i).name;
      name.pose.position.x = pose.x;
      name.pose.position.y = pose.y;
      name.pose.position.z = kRobotHeight + 0.15;
      name.scale.z = 0.15;  // text height, m
      array.markers.push_back(name);
    }
  }

  /// Swept floor 0 (white in rviz's "map" colours), floor not yet swept −1 (unknown),
  /// furniture 100 (black).
  nav_msgs::OccupancyGrid coverageMap(const ros::Time& stamp) const {
    const sim::CoverageGrid grid = sim_.unionCoverageGrid();
    nav_msgs::OccupancyGrid map;
    map.header.stamp = stamp;
    map.header.frame_id = "map";
    map.info.map_load_time = stamp;
    map.info.resolution = static_cast<float>(grid.cellSize());
    map.info.width = grid.columns();
    map.info.height = grid.rows();
    map.info.origin.orientation.w = 1.0;
    map.data.resize(static_cast<std::size_t>(grid.columns()) * grid.rows());
    for (int row = 0; row < grid.rows(); ++row) {
      for (int column = 0; column < grid.columns(); ++column) {
        const bool free = grid.isFree(column, row);
        map.data[row * grid.columns() + column] = !free ? 100 : grid.isSwept(column, row) ? 0 : -1;
      }
    }
    return map;
  }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  sim::MultiRobotSimulator sim_;
  const bool use_sim_time_;
  long steps_ = 0;  ///< steps since start (never reset: simulated time only moves forward)

  /// One robot's topics, latest command and trail.
  struct RobotIo {
    std::string prefix;                  ///< "" for the unnamed robot, "<name>/" for a named one
    std::string odom_frame, base_frame;  ///< odom and base_link, or <name>/odom, <name>/base_link
    ros::Publisher odom_pub, bumper_pub, coverage_pub;
    ros::Subscriber cmd_sub;
    sim::Velocity command;
    std::optional<ros::Time> command_time;
    visualization_msgs::Marker trail;
  };
  std::vector<RobotIo> robots_;
  std::vector<sim::Velocity> commands_ = std::vector<sim::Velocity>(robots_.size());
  std::vector<geometry_msgs::TransformStamped> transforms_;

  ros::Publisher clock_pub_, markers_pub_, coverage_pub_, coverage_map_pub_;
  ros::ServiceServer reset_srv_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;

  std::vector<visualization_msgs::Marker> wall_markers_;
  ros::WallTime last_markers_, last_coverage_, last_coverage_map_;
};

}  // namespace
}  // namespace roomba_rrt

int main(int argc, char** argv) {
  ros::init(argc, argv, "roomba_sim");
  ros::NodeHandle pnh("~");
  const bool use_sim_time = ros::param::param("/use_sim_time", false);
  roomba_rrt::sim::World world;
  try {
    world = roomba_rrt::loadWorldParameters(pnh);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL("roomba_sim: invalid world: %s", e.what());
    return 1;
  }
  if (!use_sim_time && world.real_time_factor != 1.0) {
    ROS_WARN("roomba_sim: ~real_time_factor %g needs /use_sim_time true; running in real time",
             world.real_time_factor);
  }
  roomba_rrt::nodes::MasterWatch master_watch;
  roomba_rrt::RoombaSimNode node(world, use_sim_time);
  ROS_INFO("roomba_sim: %.1f x %.1f m room, %zu pieces of furniture, %zu robot%s, %s", world.width,
           world.height, world.circles.size() + world.rectangles.size(),
           std::max<std::size_t>(1, world.robots.size()), world.robots.size() > 1 ? "s" : "",
           use_sim_time ? "publishing /clock" : "wall-clock time");
  node.run();
  return master_watch.exitCode();
}
