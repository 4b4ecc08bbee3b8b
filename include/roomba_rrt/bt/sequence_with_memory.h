// SequenceWithMemory: a Sequence that does not start again from its first child after a failure.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from left to right like SequenceNode, but remembers its place across
/// failures (BehaviorTree.CPP v4's SequenceWithMemory, v3's SequenceStar): children that
/// succeeded are not ticked again until the whole sequence has succeeded.
///
/// When the current child returns
/// - SUCCESS: the next child is entered and ticked in the same tick; after the last child the
///   node returns SUCCESS and its next tick starts again from the first child.
/// - FAILURE: the node returns FAILURE; its next tick resumes at the child that failed (the
///   children before it are not re-checked).
/// - RUNNING: the node returns RUNNING and ticks the same child next time.
/// - SKIPPED: as SUCCESS, but if every child was skipped the node returns SKIPPED.
///
/// Halting it halts the running child and keeps the place, as BehaviorTree.CPP v4 does.
class SequenceWithMemory final : public ControlNode {
 public:
  using ControlNode::ControlNode;

 private:
  Status onTick() override;

  std::size_t current_ = 0;  ///< the child ticked next; reset only after the last child succeeds
  bool executed_ = false;    ///< a child was not skipped since current_ was 0
};

}  // namespace roomba_rrt::bt
