#include "roomba_rrt/bt/try_catch_node.h"

#include <string>

namespace roomba_rrt::bt {

std::string TryCatchNode::childCountProblem(std::size_t children) const {
  if (children >= 2) return "";
  return "needs a try child and the catch child, got " + std::to_string(children);
}

Status TryCatchNode::tickCatch() {
  catching_ = true;
  const Status status = children_.back()->tick();
  if (status == Status::kRunning) return Status::kRunning;
  catching_ = false;
  return Status::kFailure;
}

Status TryCatchNode::onTick() {
  if (catching_) return tickCatch();
  const std::size_t tries = children_.size() - 1;
  while (current_ < tries) {
    const Status status = children_[current_]->tick();
    switch (status) {
      case Status::kSuccess:
        executed_ = true;
        ++current_;
        break;
      case Status::kSkipped:
        ++current_;
        break;
      case Status::kFailure:
        haltChildren();
        current_ = 0;
        return tickCatch();
      case Status::kRunning:
        return Status::kRunning;
      default:
        throwImpossibleStatus("TryCatch", status);
    }
  }
  current_ = 0;
  return executed_ ? Status::kSuccess : Status::kSkipped;
}

void TryCatchNode::onHalt() {
  const bool in_try = !catching_;
  haltChildren();
  if (catch_on_halt_ && in_try) {
    children_.back()->tick();
    children_.back()->halt();  // best effort: a catch still running is stopped
  }
  catching_ = false;
}

}  // namespace roomba_rrt::bt
