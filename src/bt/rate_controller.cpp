#include "roomba_rrt/bt/rate_controller.h"

#include <cmath>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

RateController::RateController(std::string name, double hz, double tick_rate,
                               const Blackboard& clock)
    : DecoratorNode(std::move(name)), clock_(clock), period_(1) {
  if (!(std::isfinite(hz) && hz > 0)) {
    throw util::InvalidInput("hz", "must be finite and > 0, got " + util::show(hz));
  }
  if (!(std::isfinite(tick_rate) && tick_rate > 0)) {
    throw util::InvalidInput("tick_rate", "must be finite and > 0, got " + util::show(tick_rate));
  }
  const double ticks = std::round(tick_rate / hz);
  period_ = ticks < 1      ? 1
            : ticks > 1e15 ? static_cast<std::uint64_t>(1e15)
                           : static_cast<std::uint64_t>(ticks);
}

Status RateController::onTick() {
  const std::uint64_t now = clock_.tick();
  const bool new_run = last_tick_ == 0 || now != last_tick_ + 1;
  last_tick_ = now;
  if (!child_->isRunning()) {
    if (!new_run && now - start_tick_ < period_) return Status::kRunning;  // hold the result
    start_tick_ = now;
  }
  const Status status = child_->tick();
  switch (status) {
    case Status::kFailure:
      last_tick_ = 0;  // the next tick starts a new run
      return status;
    case Status::kSuccess:
    case Status::kRunning:
      return status;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("RateController", status);
  }
}

}  // namespace roomba_rrt::bt
