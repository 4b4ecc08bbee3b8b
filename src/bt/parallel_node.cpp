#include "roomba_rrt/bt/parallel_node.h"

#include <string>

namespace roomba_rrt::bt {

ParallelNode::ParallelNode(std::string name, int success_count, int failure_count)
    : ControlNode(std::move(name)), success_count_(success_count), failure_count_(failure_count) {}

long childThreshold(int count, std::size_t children) {
  const long n = static_cast<long>(children);
  return count < 0 ? n + count + 1 : count;
}

std::string childThresholdProblem(const char* port, int count, std::size_t children) {
  const long needed = childThreshold(count, children);
  if (needed >= 1 && needed <= static_cast<long>(children)) return "";
  return std::string(port) + "=\"" + std::to_string(count) + "\" asks for " +
         std::to_string(needed) + " children, not 1 to the " + std::to_string(children) + " it has";
}

std::string ParallelNode::childCountProblem(std::size_t children) const {
  const std::string problem = childThresholdProblem("success_count", success_count_, children);
  return problem.empty() ? childThresholdProblem("failure_count", failure_count_, children)
                         : problem;
}

void ParallelNode::onEnter() {
  finished_.assign(children_.size(), false);
  successes_ = 0;
  failures_ = 0;
}

Status ParallelNode::onTick() {
  const long n = static_cast<long>(children_.size());
  const long needed_successes = childThreshold(success_count_, children_.size());
  const long needed_failures = childThreshold(failure_count_, children_.size());
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < children_.size(); ++i) {
    if (finished_[i]) continue;
    const Status status = children_[i]->tick();
    switch (status) {
      case Status::kSuccess:
        finished_[i] = true;
        ++successes_;
        break;
      case Status::kFailure:
        finished_[i] = true;
        ++failures_;
        break;
      case Status::kRunning:
        break;
      case Status::kSkipped:
        ++skipped;
        break;
      default:
        throwImpossibleStatus("Parallel", status);
    }
    // With success_count < 0 ("all"), a skipped child counts as one that succeeded (BT.CPP).
    const long skipped_as_success = success_count_ < 0 ? static_cast<long>(skipped) : 0;
    if (successes_ + skipped_as_success >= needed_successes) {
      haltChildren();
      return Status::kSuccess;
    }
    if (failures_ >= needed_failures || n - failures_ < needed_successes) {
      haltChildren();
      return Status::kFailure;
    }
  }
  return skipped == children_.size() ? Status::kSkipped : Status::kRunning;
}

}  // namespace roomba_rrt::bt
