#include "roomba_rrt/bt/if_then_else_node.h"

#include <string>

namespace roomba_rrt::bt {

std::string IfThenElseNode::childCountProblem(std::size_t children) const {
  if (children == 2 || children == 3) return "";
  return "needs 2 or 3 children (if, then, else), got " + std::to_string(children);
}

Status IfThenElseNode::onTick() {
  if (branch_ == 0) {
    const Status condition = children_[0]->tick();
    switch (condition) {
      case Status::kSuccess:
        branch_ = 1;
        break;
      case Status::kFailure:
        if (children_.size() < 3) return Status::kFailure;
        branch_ = 2;
        break;
      case Status::kRunning:
      case Status::kSkipped:  // no branch chosen
        return condition;
      default:
        throwImpossibleStatus("IfThenElse", condition);
    }
  }
  return children_[branch_]->tick();
}

}  // namespace roomba_rrt::bt
