#include "roomba_rrt/bt/retry_node.h"

#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::bt {

RetryNode::RetryNode(std::string name, int num_attempts)
    : DecoratorNode(std::move(name)), num_attempts_(num_attempts) {
  if (num_attempts < 1 && num_attempts != -1) {
    throw util::InvalidInput("num_attempts",
                             "must be >= 1 or -1 (unlimited), got " + std::to_string(num_attempts));
  }
}

Status RetryNode::onTick() {
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
      return Status::kSuccess;
    case Status::kFailure:
      ++failed_;
      if (num_attempts_ != -1 && failed_ >= num_attempts_) return Status::kFailure;
      return Status::kRunning;  // the child is not running, so the next tick enters it anew
    case Status::kRunning:
      return Status::kRunning;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("Retry", status);
  }
}

}  // namespace roomba_rrt::bt
