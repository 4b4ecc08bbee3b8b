#include "roomba_rrt/bt/pipeline_sequence.h"

namespace roomba_rrt::bt {

Status PipelineSequence::onTick() {
  for (std::size_t i = 0; i < children_.size(); ++i) {
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kSuccess:
        break;
      case Status::kFailure:
        haltChildren();
        return Status::kFailure;
      case Status::kRunning:
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
  return Status::kSuccess;
}

}  // namespace roomba_rrt::bt
