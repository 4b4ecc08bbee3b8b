#include "roomba_rrt/bt/inverter_node.h"

namespace roomba_rrt::bt {

Status InverterNode::onTick() {
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
      return Status::kFailure;
    case Status::kFailure:
      return Status::kSuccess;
    case Status::kRunning:
      return Status::kRunning;
    case Status::kSkipped:  // the child did not run: neither does this node
      return Status::kSkipped;
    default:
      throwImpossibleStatus("Inverter", status);
  }
}

}  // namespace roomba_rrt::bt
