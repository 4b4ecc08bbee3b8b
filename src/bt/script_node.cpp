#include "roomba_rrt/bt/script_node.h"

namespace roomba_rrt::bt {

Status ScriptNode::onTick() {
  try {
    script_.evaluate(board_);
    return Status::kSuccess;
  } catch (const ScriptError&) {
    return Status::kFailure;
  }
}

Status ScriptCondition::onTick() {
  try {
    return script_.isTrue(board_) ? Status::kSuccess : Status::kFailure;
  } catch (const ScriptError&) {
    return Status::kFailure;
  }
}

}  // namespace roomba_rrt::bt
