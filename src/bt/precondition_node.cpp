#include "roomba_rrt/bt/precondition_node.h"

namespace roomba_rrt::bt {

Status PreconditionNode::onTick() {
  if (!child_->isRunning()) {
    try {
      if (!condition_.isTrue(board_)) return otherwise_;
    } catch (const ScriptError&) {
      return Status::kFailure;
    }
  }
  return child_->tick();
}

}  // namespace roomba_rrt::bt
