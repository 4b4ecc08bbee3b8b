// KeepRunningUntilFailure (BehaviorTree.CPP): run the child again and again until it fails.
#pragma once

#include "roomba_rrt/bt/decorator_node.h"

namespace roomba_rrt::bt {

/// Restarts its child after every success, so it never succeeds itself. Each restart enters the
/// child on the next tick (a child that succeeds at once cannot spin inside one tick).
///
/// When the child returns
/// - SUCCESS: returns RUNNING; the child is entered anew on the next tick.
/// - FAILURE: returns FAILURE.
/// - RUNNING: returns RUNNING.
/// - SKIPPED: returns RUNNING (as BT.CPP).
class KeepRunningUntilFailure final : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;

 private:
  Status onTick() override;
};

}  // namespace roomba_rrt::bt
