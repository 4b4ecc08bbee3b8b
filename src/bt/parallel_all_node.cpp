#include "roomba_rrt/bt/parallel_all_node.h"

#include <string>

namespace roomba_rrt::bt {

ParallelAllNode::ParallelAllNode(std::string name, int max_failures)
    : ControlNode(std::move(name)), max_failures_(max_failures) {}

std::string ParallelAllNode::childCountProblem(std::size_t children) const {
  return childThresholdProblem("max_failures", max_failures_, children);
}

void ParallelAllNode::onEnter() {
  finished_.assign(children_.size(), false);
  done_ = 0;
  failures_ = 0;
}

Status ParallelAllNode::onTick() {
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < children_.size(); ++i) {
    if (finished_[i]) continue;
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kSuccess:
        break;
      case Status::kFailure:
        ++failures_;
        break;
      case Status::kRunning:
        continue;
      case Status::kSkipped:
        ++skipped;
        continue;
      default:
        throwImpossibleStatus("ParallelAll", status);
    }
    finished_[i] = true;
    ++done_;
  }
  if (skipped == children_.size()) return Status::kSkipped;
  if (done_ + skipped < children_.size()) return Status::kRunning;
  return failures_ >= childThreshold(max_failures_, children_.size()) ? Status::kFailure
                                                                      : Status::kSuccess;
}

}  // namespace roomba_rrt::bt
