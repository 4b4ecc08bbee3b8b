#include "roomba_rrt/bt/delay_node.h"

#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

DelayNode::DelayNode(std::string name, long ticks, const Blackboard& clock)
    : DecoratorNode(std::move(name)), clock_(clock), ticks_(static_cast<std::uint64_t>(ticks)) {
  if (ticks < 0) throw util::InvalidInput("ticks", "must be >= 0, got " + std::to_string(ticks));
}

Status DelayNode::onTick() {
  if (!child_->isRunning() && clock_.tick() - start_ < ticks_) return Status::kRunning;
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
    case Status::kFailure:
    case Status::kRunning:
      return status;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("Delay", status);
  }
}

}  // namespace roomba_rrt::bt
