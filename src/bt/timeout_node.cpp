#include "roomba_rrt/bt/timeout_node.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

TimeoutNode::TimeoutNode(std::string name, long ticks)
    : DecoratorNode(std::move(name)), ticks_(ticks) {
  if (ticks < 1) throw util::InvalidInput("ticks", "must be >= 1, got " + std::to_string(ticks));
}

long TimeoutNode::ticksFor(long msec, double tick_rate) {
  const double ticks = std::round(static_cast<double>(msec) * tick_rate / 1000.0);
  if (ticks >= static_cast<double>(std::numeric_limits<long>::max())) {
    return std::numeric_limits<long>::max();
  }
  return std::max(1L, static_cast<long>(ticks));
}

Status TimeoutNode::onTick() {
  const Status status = child_->tick();
  ++elapsed_;
  switch (status) {
    case Status::kSuccess:
    case Status::kFailure:
      return status;
    case Status::kRunning:
      if (elapsed_ < ticks_) return Status::kRunning;
      child_->halt();
      return Status::kFailure;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("Timeout", status);
  }
}

}  // namespace roomba_rrt::bt
