#include "roomba_rrt/bt/keep_running_until_failure.h"

namespace roomba_rrt::bt {

Status KeepRunningUntilFailure::onTick() {
  const Status status = child_->tick();
  switch (status) {
    case Status::kSuccess:
    case Status::kRunning:
      return Status::kRunning;  // after a success the child is not running: entered anew
    case Status::kFailure:
      return Status::kFailure;
    case Status::kSkipped:  // as BT.CPP: keep running
      return Status::kRunning;
    default:
      throwImpossibleStatus("KeepRunningUntilFailure", status);
  }
}

}  // namespace roomba_rrt::bt
