// ReactiveSelector (BehaviorTree.CPP's ReactiveFallback): a Selector that re-checks every earlier
// child on every tick.
#pragma once

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from the first one on *every* tick, so a higher-priority child preempts a
/// lower-priority one as soon as it stops failing.
///
/// When a child returns
/// - SUCCESS: every running child after it is halted and the ReactiveSelector returns SUCCESS.
/// - FAILURE: the next child is ticked in the same tick; after the last child the
///   ReactiveSelector returns FAILURE.
/// - RUNNING: every running child after it is halted (a higher-priority child took over) and the
///   ReactiveSelector returns RUNNING.
/// - SKIPPED: as FAILURE, but if every child was skipped it returns SKIPPED.
///
/// Children that finished are entered anew when they are ticked again on the next tick.
class ReactiveSelector final : public ControlNode {
 public:
  using ControlNode::ControlNode;

 private:
  Status onTick() override;
};

}  // namespace roomba_rrt::bt
