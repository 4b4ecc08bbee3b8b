#include "roomba_rrt/bt/sequence_node.h"

namespace roomba_rrt::bt {

Status SequenceNode::onTick() {
  while (current_ < children_.size()) {
    const bool was_running = children_[current_]->isRunning();
    const Status status = children_[current_]->tick();
    switch (status) {
      case Status::kSuccess:
        executed_ = true;
        ++current_;  // enter and tick the next child in this same tick
        if (async_ && !was_running && current_ < children_.size()) return Status::kRunning;
        break;
      case Status::kSkipped:
        ++current_;
        break;
      case Status::kFailure:
        current_ = 0;
        return Status::kFailure;
      case Status::kRunning:
        return Status::kRunning;
      default:
        throwImpossibleStatus("Sequence", status);
    }
  }
  current_ = 0;
  return executed_ ? Status::kSuccess : Status::kSkipped;
}

}  // namespace roomba_rrt::bt
