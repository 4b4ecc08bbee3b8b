#include "roomba_rrt/bt/tree_node.h"

#include "roomba_rrt/bt/node_conditions.h"

namespace roomba_rrt::bt {

Status TreeNode::tickWithExtras() {
  std::optional<Status> decided;
  if (conditions_) decided = conditions_->before(running_);
  Status status;
  if (decided) {
    status = *decided;
    halt();  // only `_while` decides for a running node: it stops it
  } else {
    if (!running_) onEnter();
    status = onTick();
    running_ = status == Status::kRunning;
  }
  if (conditions_ && (status == Status::kSuccess || status == Status::kFailure)) {
    status = conditions_->after(status);
  }
  last_status_ = status;  // for monitors, as tick() does
  ++ticks_;
  if (observer_) observer_->onStatus(*this, status);
  return status;
}

void TreeNode::afterHalt() {
  if (conditions_) conditions_->halted();
  if (observer_) observer_->onHalted(*this);
}

}  // namespace roomba_rrt::bt
