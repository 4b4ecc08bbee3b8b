#include "roomba_rrt/bt/run_once_node.h"

namespace roomba_rrt::bt {

Status RunOnceNode::onTick() {
  if (done_) return then_skip_ ? Status::kSkipped : result_;
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
    case Status::kFailure:
      done_ = true;
      result_ = status;
      return status;
    case Status::kRunning:
    case Status::kSkipped:
      return status;
    default:
      throwImpossibleStatus("RunOnce", status);
  }
}

}  // namespace roomba_rrt::bt
