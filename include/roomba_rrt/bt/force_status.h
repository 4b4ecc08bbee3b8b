// ForceSuccess and ForceFailure (BehaviorTree.CPP's decorators): the child's outcome replaced.
#pragma once

#include "roomba_rrt/bt/decorator_node.h"

namespace roomba_rrt::bt {

/// Runs its child and reports `kResult` (SUCCESS or FAILURE) whatever it finished with.
///
/// When the child returns
/// - SUCCESS: returns `kResult`.
/// - FAILURE: returns `kResult`.
/// - RUNNING: returns RUNNING.
/// - SKIPPED: returns SKIPPED.
template <Status kResult>
class ForceStatus final : public DecoratorNode {
  static_assert(kResult != Status::kRunning, "ForceStatus forces SUCCESS or FAILURE");

 public:
  using DecoratorNode::DecoratorNode;

 private:
  Status onTick() override {
    const Status status = child_->tick();
    switch (status) {
      case Status::kSuccess:
      case Status::kFailure:
        return kResult;
      case Status::kRunning:
        return Status::kRunning;
      case Status::kSkipped:
        return Status::kSkipped;
      default:
        throwImpossibleStatus(kResult == Status::kSuccess ? "ForceSuccess" : "ForceFailure",
                              status);
    }
  }
};

using ForceSuccess = ForceStatus<Status::kSuccess>;
using ForceFailure = ForceStatus<Status::kFailure>;

}  // namespace roomba_rrt::bt
