#include "roomba_rrt/bt/repeat_node.h"

#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

RepeatNode::RepeatNode(std::string name, int num_cycles)
    : DecoratorNode(std::move(name)), num_cycles_(num_cycles) {
  if (num_cycles < 1 && num_cycles != -1) {
    throw util::InvalidInput("num_cycles",
                             "must be >= 1 or -1 (forever), got " + std::to_string(num_cycles));
  }
}

Status RepeatNode::onTick() {
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
      ++done_;
      if (num_cycles_ != -1 && done_ >= num_cycles_) return Status::kSuccess;
      return Status::kRunning;  // the child is not running, so the next tick enters it anew
    case Status::kFailure:
      return Status::kFailure;
    case Status::kRunning:
      return Status::kRunning;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("Repeat", status);
  }
}

}  // namespace roomba_rrt::bt
