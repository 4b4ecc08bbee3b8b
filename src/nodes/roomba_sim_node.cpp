// roomba_sim: the simulated Roomba as a ROS node — a thin adapter around
// roomba_rrt::sim::Simulator.
//
// Subscribes /cmd_vel; publishes /odom, /bumper, tf odom→base_link (+ static map→odom, the
// identity: odometry is perfect and in room coordinates), /clock when /use_sim_time is true,
// ~markers, ~coverage, ~coverage_map; service ~reset. Parameters: see README.md, "The simulated
// Roomba".
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
#include "roomba_rrt/sim/simulator.h"
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
      : pnh_("~"), sim_(world), use_sim_time_(use_sim_time) {
    // Deep queues: at real_time_factor 50 these go out 3000 times per second, and a subscriber
    // that is descheduled for a moment must not lose any.
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", kStateQueue);
    bumper_pub_ = nh_.advertise<roomba_rrt::Bumper>("bumper", kStateQueue);
    if (use_sim_time_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("clock", 10);
    markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    coverage_pub_ = pnh_.advertise<std_msgs::Float32>("coverage", 1, true);
    coverage_map_pub_ = pnh_.advertise<nav_msgs::OccupancyGrid>("coverage_map", 1, true);
    cmd_sub_ = nh_.subscribe("cmd_vel", 10, &RoombaSimNode::onCommand, this,
                             ros::TransportHints().tcpNoDelay());
    reset_srv_ = pnh_.advertiseService("reset", &RoombaSimNode::onReset, this);
    publishStaticTransform();
    wall_markers_ = worldMarkers();
    trail_ = makeMarker("trail", 0, visualization_msgs::Marker::LINE_STRIP, kTrailColour);
    trail_.scale.x = 0.02;  // line width, m
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
      const sim::BumperState bumper = sim_.senseContact();
      publishState(now, bumper);
      sim_.move(activeCommand(now));
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

  void onCommand(const geometry_msgs::Twist& msg) {
    if (!std::isfinite(msg.linear.x) || !std::isfinite(msg.angular.z)) {
      ROS_WARN_THROTTLE(1.0,
                        "roomba_sim: rejecting /cmd_vel with a NaN or infinite component "
                        "(linear.x=%g, angular.z=%g)",
                        msg.linear.x, msg.angular.z);
      return;
    }
    command_ = {msg.linear.x, msg.angular.z};  // clamped by the simulator
    command_time_ = currentTime();
  }

  /// The latest command, or a stop when it is older than command_timeout.
  sim::Velocity activeCommand(const ros::Time& now) const {
    if (!command_time_ || (now - *command_time_).toSec() > sim_.world().command_timeout) return {};
    return command_;
  }

  bool onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    sim_.reset();
    command_ = {};
    command_time_.reset();
    trail_.points.clear();
    ROS_INFO("roomba_sim: reset to the initial pose, coverage cleared");
    return true;
  }

  void publishStaticTransform() {
    geometry_msgs::TransformStamped map_to_odom;
    map_to_odom.header.stamp = ros::Time::now();
    map_to_odom.header.frame_id = "map";
    map_to_odom.child_frame_id = "odom";
    map_to_odom.transform.rotation.w = 1.0;
    static_tf_.sendTransform(map_to_odom);
  }

  void publishState(const ros::Time& stamp, const sim::BumperState& bumper) {
    const sim::Pose2D& pose = sim_.pose();
    const sim::Velocity applied = sim_.lastCommand();
    if (use_sim_time_) {
      rosgraph_msgs::Clock clock;
      clock.clock = stamp;
      clock_pub_.publish(clock);
    }
    nav_msgs::Odometry odom;
    odom.header.stamp = stamp;
    odom.header.frame_id = "odom";
    odom.child_frame_id = "base_link";
    odom.pose.pose.position.x = pose.x;
    odom.pose.pose.position.y = pose.y;
    odom.pose.pose.orientation = yawToQuaternion(pose.theta);
    odom.twist.twist.linear.x = applied.v;
    odom.twist.twist.angular.z = applied.w;
    odom_pub_.publish(odom);

    roomba_rrt::Bumper bumper_msg;
    bumper_msg.header.stamp = stamp;
    bumper_msg.header.frame_id = "base_link";
    bumper_msg.pressed = bumper.pressed;
    bumper_msg.left = bumper.left;
    bumper_msg.right = bumper.right;
    bumper_pub_.publish(bumper_msg);

    geometry_msgs::TransformStamped tf;
    tf.header = odom.header;
    tf.child_frame_id = "base_link";
    tf.transform.translation.x = pose.x;
    tf.transform.translation.y = pose.y;
    tf.transform.rotation = odom.pose.pose.orientation;
    tf_.sendTransform(tf);
  }

  /// Markers, coverage and the coverage map, a few times per wall-clock second.
  void publishSlowTopics(const ros::Time& stamp) {
    extendTrail();
    const ros::WallTime wall = ros::WallTime::now();
    if ((wall - last_markers_).toSec() >= kMarkerPeriod) {
      last_markers_ = wall;
      if (markers_pub_.getNumSubscribers() > 0) markers_pub_.publish(robotMarkers(stamp));
    }
    if ((wall - last_coverage_).toSec() >= kCoveragePeriod) {
      last_coverage_ = wall;
      std_msgs::Float32 coverage;
      coverage.data = static_cast<float>(sim_.coverage());
      coverage_pub_.publish(coverage);
    }
    if ((wall - last_coverage_map_).toSec() >= kCoverageMapPeriod) {
      last_coverage_map_ = wall;
      if (coverage_map_pub_.getNumSubscribers() > 0) coverage_map_pub_.publish(coverageMap(stamp));
    }
  }

  void extendTrail() {
    const sim::Pose2D& pose = sim_.pose();
    if (!trail_.points.empty()) {
      const auto& last = trail_.points.back();
      if (std::hypot(pose.x - last.x, pose.y - last.y) < kTrailSpacing) return;
    }
    if (trail_.points.size() >= kTrailLength) {
      trail_.points.erase(trail_.points.begin(), trail_.points.begin() + kTrailLength / 2);
    }
    geometry_msgs::Point p;
    p.x = pose.x;
    p.y = pose.y;
    p.z = 0.01;
    trail_.points.push_back(p);
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
    using visualization_msgs::Marker;
    const sim::Pose2D& pose = sim_.pose();
    const double r = sim_.world().robot_radius;
    visualization_msgs::MarkerArray array;
    array.markers = wall_markers_;

    const bool pressed = sim_.bumper().pressed;  // red while the bumper is pressed
    auto robot = makeMarker("robot", 0, Marker::CYLINDER, pressed ? kPressedColour : kRobotColour);
    robot.pose.position.x = pose.x;
    robot.pose.position.y = pose.y;
    robot.pose.position.z = 0.5 * kRobotHeight;
    robot.scale.x = robot.scale.y = 2 * r;
    robot.scale.z = kRobotHeight;
    array.markers.push_back(robot);

    auto heading = makeMarker("heading", 0, Marker::ARROW, Rgb{1.0, 1.0, 1.0});
    heading.pose.position.x = pose.x;
    heading.pose.position.y = pose.y;
    heading.pose.position.z = kRobotHeight + 0.01;
    heading.pose.orientation = yawToQuaternion(pose.theta);
    heading.scale.x = r;
    heading.scale.y = 0.04;
    heading.scale.z = 0.04;
    array.markers.push_back(heading);

    if (trail_.points.size() >= 2) array.markers.push_back(trail_);
    for (auto& m : array.markers) m.header.stamp = stamp;
    return array;
  }

  /// Swept floor 0 (white in rviz's "map" colours), floor not yet swept −1 (unknown),
  /// furniture 100 (black).
  nav_msgs::OccupancyGrid coverageMap(const ros::Time& stamp) const {
    const sim::CoverageGrid& grid = sim_.coverageGrid();
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
  sim::Simulator sim_;
  const bool use_sim_time_;
  long steps_ = 0;  ///< steps since start (never reset: simulated time only moves forward)

  sim::Velocity command_;
  std::optional<ros::Time> command_time_;

  ros::Publisher odom_pub_, bumper_pub_, clock_pub_, markers_pub_, coverage_pub_, coverage_map_pub_;
  ros::Subscriber cmd_sub_;
  ros::ServiceServer reset_srv_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;

  std::vector<visualization_msgs::Marker> wall_markers_;
  visualization_msgs::Marker trail_;
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
  ROS_INFO("roomba_sim: %.1f x %.1f m room, %zu pieces of furniture, %s", world.width, world.height,
           world.circles.size() + world.rectangles.size(),
           use_sim_time ? "publishing /clock" : "wall-clock time");
  node.run();
  return master_watch.exitCode();
}
