#include "roomba_rrt/bt/while_do_else_node.h"

#include <string>

namespace roomba_rrt::bt {

std::string WhileDoElseNode::childCountProblem(std::size_t children) const {
  if (children == 2 || children == 3) return "";
  return "needs 2 or 3 children (while, do, else), got " + std::to_string(children);
}

Status WhileDoElseNode::onTick() {
  const Status condition = children_[0]->tick();
  switch (condition) {
    case Status::kSuccess:
      if (children_.size() == 3) children_[2]->halt();
      return children_[1]->tick();
    case Status::kFailure:
      children_[1]->halt();
      return children_.size() == 3 ? children_[2]->tick() : Status::kFailure;
    case Status::kRunning:
    case Status::kSkipped:
      return condition;
    default:
      throwImpossibleStatus("WhileDoElse", condition);
  }
}

}  // namespace roomba_rrt::bt
