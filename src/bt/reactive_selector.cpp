#include "roomba_rrt/bt/reactive_selector.h"

namespace roomba_rrt::bt {

Status ReactiveSelector::onTick() {
  bool executed = false;
  for (std::size_t i = 0; i < children_.size(); ++i) {
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kFailure:
        executed = true;
        break;  // tick the next child in this same tick
      case Status::kSkipped:
        break;
      case Status::kSuccess:
      case Status::kRunning:
        haltChildren(i + 1);  // a later child may have been running
        return status;
      default:
        throwImpossibleStatus("ReactiveSelector", status);
    }
  }
  return executed ? Status::kFailure : Status::kSkipped;
}

}  // namespace roomba_rrt::bt
