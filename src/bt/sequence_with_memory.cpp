#include "roomba_rrt/bt/sequence_with_memory.h"

namespace roomba_rrt::bt {

Status SequenceWithMemory::onTick() {
  while (current_ < children_.size()) {
    const Status status = children_[current_]->tick();
    switch (status) {
      case Status::kSuccess:
        executed_ = true;
        ++current_;
        break;
      case Status::kSkipped:
        ++current_;
        break;
      case Status::kFailure:  // keep the place: the next tick retries this child
      case Status::kRunning:
        executed_ = true;
        return status;
      default:
        throwImpossibleStatus("SequenceWithMemory", status);
    }
  }
  current_ = 0;
  const bool executed = executed_;
  executed_ = false;
  return executed ? Status::kSuccess : Status::kSkipped;
}

}  // namespace roomba_rrt::bt
