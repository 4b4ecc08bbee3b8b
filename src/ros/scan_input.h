// Laser scans as the nodes that map take them (roomba_mapper, roomba_bt ~unknown): a
// sensor_msgs/LaserScan as the mapper's ScanView, a tf transform as a planar pose, and the queue
// that holds each scan (or bump) until tf knows where it was taken.
#pragma once

#include <deque>
#include <functional>
#include <string>

#include <geometry_msgs/Transform.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>

#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::nodes {

/// The scan as the core takes it (its ranges are not copied: `scan` must outlive the view).
mapping::ScanView scanView(const sensor_msgs::LaserScan& scan);

/// The planar pose of a transform: "" and `pose` written, or why it is not one (a component not
/// finite, a frame tilted by more than 0.05 rad: a planar map cannot use its rays).
std::string planarPose(const geometry_msgs::Transform& transform, robot::Pose2D* pose);

/// Messages waiting for tf to know where they were taken. Each is handed to its `use`, in the
/// order they came, with the transform from `target_frame` to its frame at its stamp, as soon as
/// tf has it; one tf cannot place once messages `timeout` s newer have come (or when too many
/// wait) is dropped with a throttled warning. Never waits: a frame tf never knows, or a clock
/// that stops, holds nothing up.
class TfQueue {
 public:
  using Use = std::function<void(const geometry_msgs::Transform&)>;

  TfQueue(const tf2_ros::Buffer& tf, std::string target_frame, double timeout, std::string node)
      : tf_(tf), target_(std::move(target_frame)), timeout_(timeout), node_(std::move(node)) {}

  /// A message taken in `frame` at `stamp`; uses it and those before it that tf can place now.
  void push(const std::string& frame, const ros::Time& stamp, Use use);
  /// Uses the messages tf can place now, in order (the clock at `newest`: those it cannot, once
  /// `timeout` older, are dropped).
  void drain(const ros::Time& newest);

  static constexpr std::size_t kMaxPending = 200;  ///< 3 s of bumper at 60 Hz
  static constexpr double kWarningPeriod = 5.0;    ///< s between two warnings

 private:
  struct Pending {
    std::string frame;
    ros::Time stamp;
    Use use;
  };

  const tf2_ros::Buffer& tf_;
  std::string target_;
  double timeout_;
  std::string node_;  ///< names the node in warnings
  std::deque<Pending> pending_;
};

}  // namespace roomba_rrt::nodes
