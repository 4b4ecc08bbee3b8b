// IfThenElse (BehaviorTree.CPP): a condition chooses a branch once per run.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"

namespace roomba_rrt::bt {

/// Two or three children: if, then, else. Non-reactive: the condition is ticked until it
/// finishes, then the chosen branch runs to its end without the condition being ticked again
/// (WhileDoElse re-checks it).
///
/// When the condition (first child) returns
/// - SUCCESS: the second child is ticked in the same tick, and on the next ticks until it
///   finishes; IfThenElse returns what it returns.
/// - FAILURE: likewise the third child; without one, IfThenElse returns FAILURE.
/// - RUNNING: returns RUNNING and ticks the condition next time.
/// - SKIPPED: returns SKIPPED (no branch is chosen).
class IfThenElseNode final : public ControlNode {
 public:
  using ControlNode::ControlNode;
  std::string childCountProblem(std::size_t children) const override;

 private:
  void onEnter() override { branch_ = 0; }
  Status onTick() override;

  std::size_t branch_ = 0;  ///< 0: the condition is pending; else the branch chosen
};

}  // namespace roomba_rrt::bt
