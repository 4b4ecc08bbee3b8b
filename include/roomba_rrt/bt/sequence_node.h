// Sequence: run the children one after the other until one fails.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from left to right and *remembers* the running one: the next tick resumes
/// it without re-checking the children before it (non-reactive: ReactiveSequence re-checks them).
///
/// When the current child returns
/// - SUCCESS: the next child is entered and ticked in the same tick; after the last child the
///   Sequence returns SUCCESS and its next tick starts again from the first child.
/// - FAILURE: the Sequence returns FAILURE at once (later children are not ticked); its next tick
///   starts again from the first child.
/// - RUNNING: the Sequence returns RUNNING and ticks the same child next time.
/// - SKIPPED: as SUCCESS, but if every child was skipped the Sequence returns SKIPPED.
///
/// Halting the Sequence halts the running child and rewinds to the first child.
class SequenceNode final : public ControlNode {
 public:
  /// `async` (BehaviorTree.CPP's AsyncSequence): after a child that finished with SUCCESS in the
  /// tick it was entered in, return RUNNING and go on with the next child on the next tick, so a
  /// long row of instant children does not run in one tick.
  explicit SequenceNode(std::string name, bool async = false)
      : ControlNode(std::move(name)), async_(async) {}

 private:
  void onEnter() override {
    current_ = 0;
    executed_ = false;
  }
  Status onTick() override;

  bool async_;
  std::size_t current_ = 0;  ///< the child ticked next
  bool executed_ = false;    ///< a child was not skipped in this run
};

}  // namespace roomba_rrt::bt
