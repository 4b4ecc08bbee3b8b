#include "roomba_rrt/navigation/pose_predictor.h"

#include <cmath>

#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {

PosePredictor::PosePredictor(double latency, double rate) {
  util::requireInRange("pose_latency", latency, 0, kMaxLatency, "s");
  util::requirePositive("rate", rate);
  dt_ = 1.0 / rate;
  ticks_ = static_cast<int>(std::lround(latency * rate));
}

robot::Pose2D PosePredictor::predict(const robot::Pose2D& seen) const {
  robot::Pose2D pose = seen;
  for (const robot::Velocity& cmd : sent_) pose = robot::integrateArc(pose, cmd, dt_);
  return pose;
}

void PosePredictor::sent(const robot::Velocity& cmd) {
  if (ticks_ == 0) return;
  sent_.push_back(cmd);
  if (static_cast<int>(sent_.size()) > ticks_) sent_.pop_front();
}

}  // namespace roomba_rrt::navigation
