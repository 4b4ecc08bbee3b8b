#include "roomba_rrt/bt/recovery_node.h"

#include <stdexcept>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

RecoveryNode::RecoveryNode(std::string name, int number_of_retries)
    : ControlNode(std::move(name)), number_of_retries_(number_of_retries) {
  if (number_of_retries < 0) {
    throw util::InvalidInput("number_of_retries",
                             "must be >= 0, got " + std::to_string(number_of_retries));
  }
}

Status RecoveryNode::onTick() {
  if (children_.size() != 2) {
    throw std::logic_error(name() + ": RecoveryNode needs exactly two children");
  }
  if (!recovering_) {
    const Status status = children_[0]->tick();
    switch (status) {
      case Status::kSuccess:
      case Status::kRunning:
      case Status::kSkipped:
        return status;
      case Status::kFailure:
        if (retries_ >= number_of_retries_) return Status::kFailure;
        recovering_ = true;
        break;  // recover in this same tick
      default:
        throwImpossibleStatus("RecoveryNode", status);
    }
  }
  const Status status = children_[1]->tick();
  switch (status) {
    case Status::kSuccess:
      ++retries_;
      recovering_ = false;
      return Status::kRunning;  // the action is not running: the next tick enters it anew
    case Status::kFailure:
      recovering_ = false;
      return Status::kFailure;
    case Status::kRunning:
      return Status::kRunning;
    case Status::kSkipped:
      recovering_ = false;
      return Status::kSkipped;
    default:
      throwImpossibleStatus("RecoveryNode", status);
  }
}

}  // namespace roomba_rrt::bt
