// WhileDoElse (BehaviorTree.CPP): the reactive IfThenElse, its condition re-checked every tick.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Two or three children: while, do, else. Reactive: the condition is ticked on every tick, and
/// a change of its answer halts the branch that was running.
///
/// When the condition (first child) returns
/// - SUCCESS: the else branch is halted and the do branch ticked; WhileDoElse returns its status.
/// - FAILURE: the do branch is halted and the else branch ticked, WhileDoElse returning its
///   status; without an else branch it returns FAILURE.
/// - RUNNING: returns RUNNING (neither branch is ticked nor halted); SKIPPED: returns SKIPPED,
///   likewise.
class WhileDoElseNode final : public ControlNode {
 public:
  using ControlNode::ControlNode;
  std::string childCountProblem(std::size_t children) const override;

 private:
  Status onTick() override;
};

}  // namespace roomba_rrt::bt
