// ReactiveSequence: a Sequence that re-checks every earlier child on every tick.
#pragma once

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from the first one on *every* tick, so earlier children (typically
/// conditions such as "bumper released") keep guarding the running one.
///
/// When a child returns
/// - SUCCESS: the next child is ticked in the same tick; after the last child the
///   ReactiveSequence returns SUCCESS.
/// - FAILURE: every running child after it is halted and the ReactiveSequence returns FAILURE.
/// - RUNNING: every running child after it is halted (an earlier child took over from a later
///   one) and the ReactiveSequence returns RUNNING.
/// - SKIPPED: as SUCCESS, but if every child was skipped it returns SKIPPED.
///
/// Children that finished are entered anew when they are ticked again on the next tick.
class ReactiveSequence final : public ControlNode {
 public:
  using ControlNode::ControlNode;

 private:
  Status onTick() override;
};

}  // namespace roomba_rrt::bt
