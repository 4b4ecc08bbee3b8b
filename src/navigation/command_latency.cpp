#include "roomba_rrt/navigation/command_latency.h"

#include <algorithm>
#include <cmath>

#include "roomba_rrt/util/require.h"

namespace roomba_rrt::navigation {

CommandLatency::CommandLatency(double rate) : rate_(rate) {
  util::requirePositive("rate", rate);
  latency_ = 1.0 / rate;
}

void CommandLatency::observe(double now, double pose_stamp) {
  if (!std::isfinite(now) || !std::isfinite(pose_stamp) || (started_ && now < last_now_)) {
    started_ = false;
    latency_ = 1.0 / rate_;
    return;
  }
  if (!started_) {
    started_ = true;
    last_now_ = now;
    gap_ = 1.0 / rate_;
  } else if (now > last_now_) {
    gap_ = now - last_now_;
    const double fall = std::exp(-gap_ / kReleaseTime);
    latency_ *= fall;
    last_now_ = now;
  }
  const double age = std::max(0.0, now - pose_stamp);
  const double sample = std::min(kMaxSample, age + gap_);
  latency_ = std::max(latency_, sample);
}

double LatencySpeedPolicy::scale(double latency_ticks) {
  if (!(latency_ticks > kOnTimeTicks + kSlackTicks)) return 1.0;
  return std::max(kMinScale, kOnTimeTicks / latency_ticks);
}

}  // namespace roomba_rrt::navigation
