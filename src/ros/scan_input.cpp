#include "scan_input.h"

#include <ros/console.h>
#include <tf2/exceptions.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "roomba_rrt/util/require.h"

namespace roomba_rrt::nodes {
namespace {

constexpr double kMaxTilt = 0.05;  // rad: a scan frame tilted more is not planar

}  // namespace

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

void TfQueue::push(const std::string& frame, const ros::Time& stamp, Use use) {
  pending_.push_back({frame, stamp, std::move(use)});
  drain(stamp);
}

void TfQueue::drain(const ros::Time& newest) {
  while (!pending_.empty()) {
    const Pending& p = pending_.front();
    std::string why;
    if (tf_.canTransform(target_, p.frame, p.stamp, &why)) {
      p.use(tf_.lookupTransform(target_, p.frame, p.stamp).transform);
    } else if (newest - p.stamp <= ros::Duration(timeout_) && pending_.size() <= kMaxPending) {
      return;  // tf may still come
    } else {
      ROS_WARN_THROTTLE(kWarningPeriod, "%s: no pose of %s in %s at %.3f s: %s", node_.c_str(),
                        p.frame.c_str(), target_.c_str(), p.stamp.toSec(), why.c_str());
    }
    pending_.pop_front();
  }
}

}  // namespace roomba_rrt::nodes
