// The roomba_sim node (roomba_sim.h): world parameters, topics, tf, clock, reset, reconfigure.
#include "roomba_sim.h"

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <roomba_rrt/Bumper.h>
#include <roomba_rrt/RoombaSimConfig.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float32.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "map_messages.h"
#include "master_watch.h"
#include "node_params.h"
#include "reconfigure.h"
#include "roomba_rrt/sensors/scanner.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"
#include "shutdown_grace.h"
#include "sim_ros.h"

namespace roomba_rrt::sim_node {
namespace {

using world::World;
using Clock = std::chrono::steady_clock;        // the node's one wall clock
using Seconds = std::chrono::duration<double>;  // of wall-clock time

constexpr Seconds kMarkerPeriod(0.1);        // between ~markers (10 Hz)
constexpr Seconds kCoveragePeriod(0.5);      // between ~coverage (2 Hz)
constexpr Seconds kCoverageMapPeriod(0.5);   // between ~coverage_map (2 Hz)
constexpr std::uint32_t kStateQueue = 1000;  // /odom and /bumper publisher queues
constexpr Seconds kMaxLag(0.25);             // behind schedule before the schedule resets
constexpr Seconds kMaxSleep(0.05);           // longest uninterrupted sleep

}  // namespace

/// Reads the world file, then lets every scalar be overridden by a private parameter of the same
/// path (~real_time_factor, ~initial_pose/x, ~robot/radius, ...). The values in force are written
/// back while the node runs (NodeParams deletes those the user did not set when it exits, so that
/// none is left pinned to override the next world file). Throws std::invalid_argument naming the
/// bad parameter.
world::WorldFile loadWorldParameters(nodes::NodeParams& params) {
  const std::string world_file =
      params.get<std::string>("world_file", nodes::packageConfigFile("roomba_world.yaml"));
  world::WorldFile file = world::readWorldFile(world_file);
  World& world = file.world;
  try {
    world::validate(world);  // the file as it is, named in the message
    world::validate(file.simulator);
  } catch (const util::InvalidInput& e) {
    // A map world starts at the map's origin unless told otherwise: ~initial_pose may move it.
    if (!(world.room.map && e.field() == "initial_pose")) throw e.in(world_file);
  }
  // What the file left to the defaults and no private parameter sets (--pose, _initial_pose/x:
  // that section is not the defaults'), said after the overrides with the values in force. A file
  // that sets nothing (e.g. truncated to a comment) runs the default room: a warning.
  const bool file_sets_nothing = world.defaulted_sections.size() == 4;
  std::vector<std::string>& defaulted = world.defaulted_sections;
  defaulted.erase(std::remove_if(defaulted.begin(), defaulted.end(),
                                 [&params](const std::string& s) { return params.has(s); }),
                  defaulted.end());
  world::RobotSpec& robot = world.robot();
  const std::vector<std::pair<const char*, double*>> overrides = {
      {"room/width", &world.room.width},
      {"room/height", &world.room.height},
      {"robot/radius", &robot.radius},
      {"robot/max_linear_speed", &robot.max_linear_speed},
      {"robot/max_angular_speed", &robot.max_angular_speed},
      {"initial_pose/x", &robot.initial_pose.x},
      {"initial_pose/y", &robot.initial_pose.y},
      {"initial_pose/theta", &robot.initial_pose.theta},
      {"step", &world.step},
      {"coverage_cell_size", &world.coverage_cell_size},
      {"command_timeout", &file.simulator.command_timeout},
      {"real_time_factor", &file.simulator.real_time_factor},
  };
  if (world.namedRobots() && params.has("initial_pose")) {
    throw std::invalid_argument("~initial_pose cannot be used with the world file's robots");
  }
  for (const auto& [name, value] : overrides) {
    // Named robots are each the world file's: their poses, radii and limits are not overridden.
    // A map's extent is its room.
    const bool robot_key = std::string(name).rfind("initial_pose/", 0) == 0 ||
                           std::string(name).rfind("robot/", 0) == 0;
    const bool applies = (!world.namedRobots() || !robot_key) &&
                         !(world.room.map && std::string(name).rfind("room/", 0) == 0);
    if (applies) *value = params.get(name, *value);
  }
  const std::string notice = world::defaultsNotice(world, world_file);
  if (file_sets_nothing && !notice.empty()) {
    ROS_WARN("roomba_sim: %s", notice.c_str());
  } else if (!notice.empty()) {
    ROS_INFO("roomba_sim: %s", notice.c_str());
  }
  world::validate(world);
  world::validate(file.simulator);
  return file;
}

class RoombaSimNode {
 public:
  RoombaSimNode(const World& world, const world::SimulatorSettings& settings, bool use_sim_time,
                bool publish_map)
      : pnh_("~"),
        sim_(world),
        scanner_(world),
        use_sim_time_(use_sim_time),
        settings_(settings),
        robots_(sim_.size()) {
    if (use_sim_time_) clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("clock", 10);
    markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    coverage_pub_ = pnh_.advertise<std_msgs::Float32>("coverage", 1, true);
    coverage_map_pub_ = pnh_.advertise<nav_msgs::OccupancyGrid>("coverage_map", 1, true);
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      RobotIo& io = robots_[i];
      const std::string& name = sim_.spec(i).name;
      io.frames = sim_node::robotFrames(name);
      const std::string& prefix = io.frames.prefix;
      // Deep queues: at real_time_factor 50 these go out 3000 times per second, and a subscriber
      // that is descheduled for a moment must not lose any.
      io.odom_pub = nh_.advertise<nav_msgs::Odometry>(prefix + "odom", kStateQueue);
      io.bumper_pub = nh_.advertise<roomba_rrt::Bumper>(prefix + "bumper", kStateQueue);
      for (const sensors::RangeSensorSpec& sensor : sim_.spec(i).sensors) {
        io.scan_pubs.push_back(nh_.advertise<sensor_msgs::LaserScan>(prefix + sensor.name, 10));
      }
      if (!name.empty()) {
        io.coverage_pub = pnh_.advertise<std_msgs::Float32>(prefix + "coverage", 1, true);
      }
      io.cmd_sub = nh_.subscribe<geometry_msgs::Twist>(
          prefix + "cmd_vel", 10,
          [this, i](const geometry_msgs::Twist::ConstPtr& msg) { onCommand(i, *msg); },
          ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
      trails_.push_back(sim_node::makeTrail(i));
    }
    reset_srv_ = pnh_.advertiseService("reset", &RoombaSimNode::onReset, this);
    if (sim_.world().room.map && publish_map) publishMap(*sim_.world().room.map);
    publishStaticTransforms();
    world_markers_ = sim_node::worldMarkers(sim_.world());
    startReconfigure();
  }

  /// The world's map on /map and /map_metadata, latched, exactly as map_server would publish
  /// the same file, so that rviz's Map display, a planner or any map_server client finds it.
  void publishMap(const geometry::OccupancyGrid& grid) {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
    map_metadata_pub_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, /*latch=*/true);
    const ros::Time stamp = ros::Time::now();
    map_pub_.publish(nodes::toMapMessage(grid, stamp));
    map_metadata_pub_.publish(nodes::toMapMetaData(grid, stamp));
    ROS_INFO("roomba_sim: map %s, %d x %d cells of %g m, on /map",
             sim_.world().room.map_file.c_str(), grid.width, grid.height, grid.resolution);
  }

  /// The fixed-step loop: sense contact, publish the state, apply the latest command, keep pace
  /// with the wall clock (× real_time_factor when the simulator owns /clock).
  void run() {
    auto next_step = Clock::now();
    while (ros::ok()) {
      ros::spinOnce();
      // Read every step: dynamic_reconfigure may change the factor between two.
      const double factor = use_sim_time_ ? settings_.real_time_factor : 1.0;
      const auto wall_step =
          std::chrono::duration_cast<Clock::duration>(Seconds(sim_.world().step / factor));
      const ros::Time now = currentTime();
      sim_.senseContact();
      publishState(now);
      publishScans(now);
      for (std::size_t i = 0; i < robots_.size(); ++i) commands_[i] = activeCommand(i, now);
      sim_.move(commands_);
      ++steps_;
      publishSlowTopics(now);

      next_step += wall_step;
      const auto wall_now = Clock::now();
      if (wall_now < next_step) {
        waitUntil(next_step);
      } else if (wall_now - next_step > kMaxLag) {
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
                        robots_[robot].frames.prefix.c_str(), msg.linear.x, msg.angular.z);
      return;
    }
    robots_[robot].command = {msg.linear.x, msg.angular.z};  // clamped by the simulator
    robots_[robot].command_time = currentTime();
  }

  /// Robot i's latest command, or a stop when it is older than command_timeout.
  robot::Velocity activeCommand(std::size_t robot, const ros::Time& now) const {
    const RobotIo& io = robots_[robot];
    if (!io.command_time || (now - *io.command_time).toSec() > settings_.command_timeout) {
      return {};
    }
    return io.command;
  }

  bool onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    sim_.reset();
    for (RobotIo& io : robots_) {
      io.command = {};
      io.command_time.reset();
    }
    for (auto& trail : trails_) trail.points.clear();
    ROS_INFO("roomba_sim: reset to the initial pose, coverage cleared");
    return true;
  }

  /// dynamic_reconfigure (cfg/RoombaSim.cfg): the real-time factor, the command timeout and
  /// every robot's speed limits, from the next step; refused (and kept) when World's rules say no.
  void startReconfigure() {
    RoombaSimConfig in_force;
    in_force.real_time_factor = settings_.real_time_factor;
    in_force.command_timeout = settings_.command_timeout;
    in_force.max_linear_speed = sim_.world().robot().max_linear_speed;
    in_force.max_angular_speed = sim_.world().robot().max_angular_speed;
    reconfigure_ = std::make_unique<nodes::Reconfigure<RoombaSimConfig>>(
        pnh_, in_force, [this](const RoombaSimConfig& c) {
          world::SimulatorSettings next;
          next.real_time_factor = c.real_time_factor;
          next.command_timeout = c.command_timeout;
          world::validate(next);
          sim_.setSpeedLimits(c.max_linear_speed, c.max_angular_speed);
          settings_ = next;
          if (!use_sim_time_ && c.real_time_factor != 1.0) {
            ROS_WARN(
                "roomba_sim: ~real_time_factor %g needs /use_sim_time true; running in real "
                "time",
                c.real_time_factor);
          }
        });
  }

  /// map → odom (or map → <name>/odom for every named robot): the identity; base_link → each
  /// sensor's frame at its mounting pose.
  void publishStaticTransforms() {
    std::vector<geometry_msgs::TransformStamped> transforms;
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      const RobotIo& io = robots_[i];
      transforms.push_back(sim_node::toMapTransform(io.frames, ros::Time::now()));
      for (const sensors::RangeSensorSpec& sensor : sim_.spec(i).sensors) {
        transforms.push_back(sim_node::toSensorTransform(sensor, io.frames, ros::Time::now()));
      }
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
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      const RobotIo& io = robots_[i];
      const robot::Pose2D& pose = sim_.pose(i);
      io.odom_pub.publish(sim_node::toOdometry(pose, sim_.lastCommand(i), io.frames, stamp));
      io.bumper_pub.publish(sim_node::toBumper(sim_.bumper(i), io.frames, stamp));
      transforms_[i] = sim_node::toOdomTransform(pose, io.frames, stamp);
    }
    tf_.sendTransform(transforms_);
  }

  /// The scans due at this step (each sensor at its rate in simulated time), taken at the poses
  /// just published on /odom and stamped with them.
  void publishScans(const ros::Time& stamp) {
    if (scanner_.empty()) return;
    poses_.resize(robots_.size());
    for (std::size_t i = 0; i < robots_.size(); ++i) poses_[i] = sim_.pose(i);
    // Simulated time since start (steps_: never reset, as the scanner wants it).
    for (const sensors::Scan& scan : scanner_.scan(steps_ * sim_.world().step, poses_)) {
      const RobotIo& io = robots_[scan.robot];
      io.scan_pubs[scan.sensor].publish(sim_node::toLaserScan(
          sim_.spec(scan.robot).sensors[scan.sensor], scan, io.frames, stamp));
    }
  }

  /// Markers, coverage and the coverage map, a few times per wall-clock second.
  void publishSlowTopics(const ros::Time& stamp) {
    for (std::size_t i = 0; i < robots_.size(); ++i)
      sim_node::extendTrail(sim_.pose(i), trails_[i]);
    const Clock::time_point wall = Clock::now();
    if (wall - last_markers_ >= kMarkerPeriod) {
      last_markers_ = wall;
      if (markers_pub_.getNumSubscribers() > 0) {
        markers_pub_.publish(sim_node::toMarkers(world_markers_, sim_, trails_, stamp));
      }
    }
    if (wall - last_coverage_ >= kCoveragePeriod) {
      last_coverage_ = wall;
      coverage_pub_.publish(sim_node::toCoverageMessage(sim_.unionCoverage()));
      for (std::size_t i = 0; i < robots_.size(); ++i) {
        if (robots_[i].coverage_pub) {
          robots_[i].coverage_pub.publish(sim_node::toCoverageMessage(sim_.coverage(i)));
        }
      }
    }
    if (wall - last_coverage_map_ >= kCoverageMapPeriod) {
      last_coverage_map_ = wall;
      if (coverage_map_pub_.getNumSubscribers() > 0) {
        coverage_map_pub_.publish(sim_node::toCoverageMap(sim_.unionCoverageGrid(), stamp));
      }
    }
  }

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  sim::MultiRobotSimulator sim_;
  sensors::Scanner scanner_;          ///< every robot's range sensors
  std::vector<robot::Pose2D> poses_;  ///< the robots' poses for the scanner
  const bool use_sim_time_;
  world::SimulatorSettings settings_;  ///< dynamic_reconfigure may change them while running
  std::unique_ptr<nodes::Reconfigure<RoombaSimConfig>> reconfigure_;
  long steps_ = 0;  ///< steps since start (never reset: simulated time only moves forward)

  /// One robot's topics and latest command.
  struct RobotIo {
    sim_node::RobotFrames frames;  ///< topic prefix and tf frames, built once
    ros::Publisher odom_pub, bumper_pub, coverage_pub;
    std::vector<ros::Publisher> scan_pubs;  ///< one per sensor, in the RobotSpec's order
    ros::Subscriber cmd_sub;
    robot::Velocity command;
    std::optional<ros::Time> command_time;
  };
  std::vector<RobotIo> robots_;
  std::vector<robot::Velocity> commands_ = std::vector<robot::Velocity>(robots_.size());
  std::vector<geometry_msgs::TransformStamped> transforms_;
  std::vector<visualization_msgs::Marker> trails_;  ///< one per robot

  ros::Publisher clock_pub_, markers_pub_, coverage_pub_, coverage_map_pub_;
  ros::Publisher map_pub_, map_metadata_pub_;  ///< latched, as map_server's
  ros::ServiceServer reset_srv_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;

  std::vector<visualization_msgs::Marker> world_markers_;
  Clock::time_point last_markers_, last_coverage_, last_coverage_map_;  ///< wall clock
};

RoombaSim::RoombaSim(const World& world, const world::SimulatorSettings& settings,
                     bool use_sim_time, bool publish_map)
    : node_(std::make_unique<RoombaSimNode>(world, settings, use_sim_time, publish_map)) {}
RoombaSim::~RoombaSim() = default;
void RoombaSim::run() { node_->run(); }

}  // namespace roomba_rrt::sim_node
