// Selector (BehaviorTree.CPP's Fallback): try the children one after the other until one
// succeeds.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Ticks its children from left to right and *remembers* the running one: the next tick resumes
/// it without re-checking the children before it (non-reactive: ReactiveSelector re-checks them).
///
/// When the current child returns
/// - SUCCESS: the Selector returns SUCCESS at once (later children are not ticked); its next tick
///   starts again from the first child.
/// - FAILURE: the next child is entered and ticked in the same tick; after the last child the
///   Selector returns FAILURE and its next tick starts again from the first child.
/// - RUNNING: the Selector returns RUNNING and ticks the same child next time.
/// - SKIPPED: as FAILURE, but if every child was skipped the Selector returns SKIPPED.
///
/// Halting the Selector halts the running child and rewinds to the first child.
class SelectorNode final : public ControlNode {
 public:
  /// `async` (BehaviorTree.CPP's AsyncSelector): after a child that finished with FAILURE in the
  /// tick it was entered in, return RUNNING and go on with the next child on the next tick, so a
  /// long row of instant children does not run in one tick.
  explicit SelectorNode(std::string name, bool async = false)
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
