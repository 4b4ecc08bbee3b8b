#include "roomba_rrt/bt/pipeline_sequence.h"

namespace roomba_rrt::bt {

Status PipelineSequence::onTick() {
  bool executed = false;
  for (std::size_t i = 0; i < children_.size(); ++i) {
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kSkipped:
        break;
      case Status::kSuccess:
        executed = true;
        break;
      case Status::kFailure:
        haltChildren();
        return Status::kFailure;
      case Status::kRunning:
        executed = true;
        if (i >= furthest_) {
          furthest_ = i;
          return Status::kRunning;
        }
        break;  // a later stage was reached: tick it too
      default:
        throwImpossibleStatus("PipelineSequence", status);
    }
  }
  haltChildren();
  return executed || furthest_ > 0 ? Status::kSuccess : Status::kSkipped;
}

}  // namespace roomba_rrt::bt
