#include "roomba_rrt/bt/reactive_sequence.h"

namespace roomba_rrt::bt {

Status ReactiveSequence::onTick() {
  bool executed = false;
  for (std::size_t i = 0; i < children_.size(); ++i) {
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kSuccess:
        executed = true;
        break;  // tick the next child in this same tick
      case Status::kSkipped:
        break;
      case Status::kFailure:
      case Status::kRunning:
        haltChildren(i + 1);  // a later child may have been running
        return status;
      default:
        throwImpossibleStatus("ReactiveSequence", status);
    }
  }
  return executed ? Status::kSuccess : Status::kSkipped;
}

}  // namespace roomba_rrt::bt
