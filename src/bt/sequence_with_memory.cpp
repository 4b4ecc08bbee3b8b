#include "roomba_rrt/bt/sequence_with_memory.h"

namespace roomba_rrt::bt {

Status SequenceWithMemory::onTick() {
  while (current_ < children_.size()) {
    const Status status = children_[current_]->tick();
    switch (status) {
      case Status::kSuccess:
        ++current_;
        break;
      case Status::kFailure:  // keep the place: the next tick retries this child
      case Status::kRunning:
        return status;
      default:
        throwImpossibleStatus("SequenceWithMemory", status);
    }
  }
  current_ = 0;
  return Status::kSuccess;
}

}  // namespace roomba_rrt::bt
