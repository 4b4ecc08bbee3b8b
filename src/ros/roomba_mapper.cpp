// The roomba_mapper node (roomba_mapper.h): parameters, scans and bumper in, map out.
#include "roomba_mapper.h"

#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <roomba_rrt/Bumper.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "map_messages.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"
#include "scan_input.h"

namespace roomba_rrt::mapper_node {
namespace {

constexpr double kWarningPeriod = 5.0;  // s between two warnings of one kind

/// The parameter each option is read from (gmapping's name where it has one).
const std::vector<std::pair<const char*, const char*>> kOptionParameters = {
    {"resolution", "delta"},
    {"xmin", "xmin"},
    {"ymin", "ymin"},
    {"xmax", "xmax"},
    {"ymax", "ymax"},
    {"max_range", "maxUrange"},
    {"occupied_threshold", "occ_thresh"},
    {"log_odds_occupied", "log_odds_occupied"},
    {"log_odds_free", "log_odds_free"},
    {"log_odds_limit", "log_odds_limit"},
    {"max_cells", "max_cells"},
};

std::string parameterOf(const std::string& field) {
  for (const auto& [option, parameter] : kOptionParameters) {
    if (field == option) return std::string("~") + parameter;
  }
  return field == "xmin, ymin, xmax, ymax" ? "~xmin, ~ymin, ~xmax, ~ymax" : "~" + field;
}

}  // namespace

MapperSettings readSettings(nodes::NodeParams& params) {
  MapperSettings s;
  mapping::MapperOptions& o = s.options;
  o.xmin = o.ymin = -10;  // 400 × 400 cells to start with; it grows as the robot sees more
  o.xmax = o.ymax = 10;
  o.max_range = 80;  // gmapping's maxUrange
  o.resolution = params.get("delta", o.resolution);
  o.xmin = params.get("xmin", o.xmin);
  o.ymin = params.get("ymin", o.ymin);
  o.xmax = params.get("xmax", o.xmax);
  o.ymax = params.get("ymax", o.ymax);
  o.max_range = params.get("maxUrange", o.max_range);
  o.occupied_threshold = params.get("occ_thresh", o.occupied_threshold);
  o.log_odds_occupied = params.get("log_odds_occupied", o.log_odds_occupied);
  o.log_odds_free = params.get("log_odds_free", o.log_odds_free);
  o.log_odds_limit = params.get("log_odds_limit", o.log_odds_limit);
  o.max_cells = params.get("max_cells", static_cast<int>(o.max_cells));
  try {
    mapping::validate(o);
  } catch (const util::InvalidInput& e) {
    throw std::invalid_argument(parameterOf(e.field()) + ": " + e.problem());
  }
  s.map_frame = params.get("map_frame", s.map_frame);
  s.odom_frame = params.get("odom_frame", s.odom_frame);
  s.base_frame = params.get("base_frame", s.base_frame);
  for (const auto& [name, frame] :
       {std::pair<const char*, const std::string*>{"~map_frame", &s.map_frame},
        {"~odom_frame", &s.odom_frame},
        {"~base_frame", &s.base_frame}}) {
    if (frame->empty()) throw std::invalid_argument(std::string(name) + ": must not be empty");
  }
  s.map_update_interval = params.get("map_update_interval", s.map_update_interval);
  util::requireInRange("~map_update_interval", s.map_update_interval, 0.01, 3600.0, "s");
  s.transform_timeout = params.get("transform_timeout", s.transform_timeout);
  util::requireInRange("~transform_timeout", s.transform_timeout, 0.0, 10.0, "s");
  s.throttle_scans = params.get("throttle_scans", s.throttle_scans);
  util::requireInRange("~throttle_scans", s.throttle_scans, 1, 1000);
  s.robot_radius = params.get("robot_radius", s.robot_radius);
  util::requireInRange("~robot_radius", s.robot_radius, 0.0, 10.0, "m");
  return s;
}

class RoombaMapperNode {
 public:
  explicit RoombaMapperNode(const MapperSettings& settings)
      : settings_(settings),
        mapper_(settings.options),
        pnh_("~"),
        listener_(tf_),
        waiting_(tf_, settings.odom_frame, settings.transform_timeout, "roomba_mapper") {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
    metadata_pub_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, /*latch=*/true);
    map_srv_ = pnh_.advertiseService("dynamic_map", &RoombaMapperNode::onGetMap, this);
    scan_sub_ = nh_.subscribe("scan", 5, &RoombaMapperNode::onScan, this);
    bumper_sub_ = nh_.subscribe("bumper", 50, &RoombaMapperNode::onBumper, this);
    timer_ = nh_.createTimer(ros::Duration(settings_.map_update_interval),
                             [this](const ros::TimerEvent&) { publishIfChanged(); });
    ROS_INFO("roomba_mapper: %s and tf %s -> scan frame in, %s (frame %s, %g m cells) every %g s",
             scan_sub_.getTopic().c_str(), settings_.odom_frame.c_str(),
             map_pub_.getTopic().c_str(), settings_.map_frame.c_str(), settings_.options.resolution,
             settings_.map_update_interval);
  }

 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    if (scans_seen_++ % settings_.throttle_scans != 0) return;
    const std::string bad = mapping::checkScan(nodes::scanView(*scan));
    if (!bad.empty()) {
      ROS_WARN_THROTTLE(kWarningPeriod, "roomba_mapper: scan skipped: %s", bad.c_str());
      return;
    }
    waiting_.push(scan->header.frame_id, scan->header.stamp,
                  [this, scan](const geometry_msgs::Transform& t) { use(t, scan.get(), nullptr); });
  }

  void onBumper(const roomba_rrt::Bumper::ConstPtr& bumper) {
    if (!bumper->pressed) return;
    waiting_.push(
        settings_.base_frame, bumper->header.stamp,
        [this, bumper](const geometry_msgs::Transform& t) { use(t, nullptr, bumper.get()); });
  }

  /// A scan or a bump, with the pose tf gave its frame.
  void use(const geometry_msgs::Transform& transform, const sensor_msgs::LaserScan* scan,
           const roomba_rrt::Bumper* bumper) {
    robot::Pose2D pose;
    std::string why = nodes::planarPose(transform, &pose);
    if (why.empty() && scan) why = mapper_.addScan(pose, nodes::scanView(*scan));
    if (!why.empty()) {
      ROS_WARN_THROTTLE(kWarningPeriod, "roomba_mapper: %s skipped: %s", scan ? "scan" : "bump",
                        why.c_str());
      return;
    }
    if (bumper) {
      mapper_.addBump(pose, settings_.robot_radius,
                      {bumper->pressed != 0, bumper->left != 0, bumper->right != 0});
    }
    changed_ = true;
    if (!published_) publishIfChanged();  // the first map at once, then at the interval
  }

  void publishIfChanged() {
    if (!changed_) return;
    changed_ = false;
    published_ = true;
    mapper_.grid(grid_);
    message_ = nodes::toMapMessage(grid_, ros::Time::now());
    message_.header.frame_id = settings_.map_frame;
    map_pub_.publish(message_);
    metadata_pub_.publish(message_.info);
  }

  bool onGetMap(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& response) {
    if (!published_) return false;  // no map yet, as gmapping answers
    publishIfChanged();
    response.map = message_;
    return true;
  }

  MapperSettings settings_;
  mapping::OccupancyMapper mapper_;
  ros::NodeHandle nh_, pnh_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  ros::Publisher map_pub_, metadata_pub_;
  ros::ServiceServer map_srv_;
  ros::Subscriber scan_sub_, bumper_sub_;
  ros::Timer timer_;
  geometry::OccupancyGrid grid_;
  nav_msgs::OccupancyGrid message_;
  /// Scans and bumps until tf knows where they were taken (~transform_timeout).
  nodes::TfQueue waiting_;
  std::size_t scans_seen_ = 0;
  bool changed_ = false, published_ = false;
};

RoombaMapper::RoombaMapper(const MapperSettings& settings)
    : node_(std::make_unique<RoombaMapperNode>(settings)) {}

RoombaMapper::~RoombaMapper() = default;

}  // namespace roomba_rrt::mapper_node
