// The roomba_mapper node (roomba_mapper.h): parameters, scans and bumper in, map out.
#include "roomba_mapper.h"

#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <roomba_rrt/Bumper.h>
#include <ros/ros.h>
#include <tf2/exceptions.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <deque>
#include <stdexcept>
#include <utility>
#include <vector>

#include "map_messages.h"
#include "roomba_rrt/util/invalid_input.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::mapper_node {
namespace {

constexpr double kWarningPeriod = 5.0;    // s between two warnings of one kind
constexpr double kMaxTilt = 0.05;         // rad: a scan frame tilted more is not planar
constexpr std::size_t kMaxPending = 200;  // messages waiting for tf (3 s of bumper at 60 Hz)

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

mapping::ScanView scanView(const sensor_msgs::LaserScan& scan) {
  return {scan.angle_min, scan.angle_max,     scan.angle_increment, scan.range_min,
          scan.range_max, scan.ranges.data(), scan.ranges.size()};
}

std::string planarPose(const geometry_msgs::Transform& t, robot::Pose2D* pose) {
  const auto& q = t.rotation;
  for (const double v : {t.translation.x, t.translation.y, t.translation.z, q.x, q.y, q.z, q.w}) {
    if (!std::isfinite(v)) return "not finite";
  }
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (norm == 0) return "rotation: a zero quaternion";
  const double x = q.x / norm, y = q.y / norm, z = q.z / norm, w = q.w / norm;
  // The angle between the frame's z axis and the map's: its z axis is (2(xz + wy), 2(yz − wx),
  // 1 − 2(x² + y²)).
  const double tilt = std::acos(std::clamp(1 - 2 * (x * x + y * y), -1.0, 1.0));
  if (tilt > kMaxTilt) {
    return "tilted by " + util::show(tilt) + " rad (a planar map takes at most " +
           util::show(kMaxTilt) + ")";
  }
  pose->x = t.translation.x;
  pose->y = t.translation.y;
  pose->theta = std::atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  return "";
}

class RoombaMapperNode {
 public:
  explicit RoombaMapperNode(const MapperSettings& settings)
      : settings_(settings), mapper_(settings.options), pnh_("~"), listener_(tf_) {
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
  /// A scan or a pressed bumper waiting for tf to know where it was taken.
  struct Pending {
    sensor_msgs::LaserScan::ConstPtr scan;  ///< or
    roomba_rrt::Bumper::ConstPtr bumper;
    const std::string& frame(const MapperSettings& s) const {
      return scan ? scan->header.frame_id : s.base_frame;
    }
    ros::Time stamp() const { return scan ? scan->header.stamp : bumper->header.stamp; }
  };

  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    if (scans_seen_++ % settings_.throttle_scans != 0) return;
    const std::string bad = mapping::checkScan(scanView(*scan));
    if (!bad.empty()) {
      ROS_WARN_THROTTLE(kWarningPeriod, "roomba_mapper: scan skipped: %s", bad.c_str());
      return;
    }
    pending_.push_back({scan, nullptr});
    drain(scan->header.stamp);
  }

  void onBumper(const roomba_rrt::Bumper::ConstPtr& bumper) {
    if (!bumper->pressed) return;
    pending_.push_back({nullptr, bumper});
    drain(bumper->header.stamp);
  }

  /// Uses the waiting messages in order, each as soon as tf has its pose in ~odom_frame at its
  /// stamp; one that tf cannot place once messages ~transform_timeout newer have come (or when
  /// too many wait) is skipped with a throttled warning. Never waits: a message whose frame tf
  /// never knows, or a clock that stops, does not hold up the timer or ~dynamic_map.
  void drain(const ros::Time& newest) {
    while (!pending_.empty()) {
      const Pending& p = pending_.front();
      const std::string& frame = p.frame(settings_);
      std::string why;
      if (tf_.canTransform(settings_.odom_frame, frame, p.stamp(), &why)) {
        use(p, tf_.lookupTransform(settings_.odom_frame, frame, p.stamp()).transform);
      } else if (newest - p.stamp() <= ros::Duration(settings_.transform_timeout) &&
                 pending_.size() <= kMaxPending) {
        return;  // tf may still come
      } else {
        ROS_WARN_THROTTLE(kWarningPeriod, "roomba_mapper: no pose of %s in %s at %.3f s: %s",
                          frame.c_str(), settings_.odom_frame.c_str(), p.stamp().toSec(),
                          why.c_str());
      }
      pending_.pop_front();
    }
  }

  void use(const Pending& p, const geometry_msgs::Transform& transform) {
    robot::Pose2D pose;
    std::string why = planarPose(transform, &pose);
    if (why.empty() && p.scan) why = mapper_.addScan(pose, scanView(*p.scan));
    if (!why.empty()) {
      ROS_WARN_THROTTLE(kWarningPeriod, "roomba_mapper: %s skipped: %s", p.scan ? "scan" : "bump",
                        why.c_str());
      return;
    }
    if (p.bumper) {
      const roomba_rrt::Bumper& b = *p.bumper;
      mapper_.addBump(pose, settings_.robot_radius, {b.pressed != 0, b.left != 0, b.right != 0});
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
  std::deque<Pending> pending_;
  std::size_t scans_seen_ = 0;
  bool changed_ = false, published_ = false;
};

RoombaMapper::RoombaMapper(const MapperSettings& settings)
    : node_(std::make_unique<RoombaMapperNode>(settings)) {}

RoombaMapper::~RoombaMapper() = default;

}  // namespace roomba_rrt::mapper_node
