// Precondition (BehaviorTree.CPP): run the child only if a script holds.
#pragma once

#include <string>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"
#include "roomba_rrt/bt/script.h"

namespace roomba_rrt::bt {

/// Checks `if` (a script, script.h) when the child is not running:
/// - true: the child is ticked, and on the following ticks until it finishes without `if` being
///   checked again; Precondition returns the child's SUCCESS, FAILURE or RUNNING.
/// - false: returns `else` (SUCCESS, FAILURE, RUNNING or SKIPPED; default FAILURE) without
///   ticking the child.
/// - not evaluable (a key never written, a type mismatch): returns FAILURE.
class PreconditionNode final : public DecoratorNode {
 public:
  static PortList providedPorts() {
    return {inputPort<std::string>("if", "the condition"),
            inputPort<std::string>("else", "what to return when it is false", "FAILURE")};
  }
  /// `otherwise` is what `else` names; `board` must outlive the node.
  PreconditionNode(std::string name, Script condition, Status otherwise, Blackboard& board)
      : DecoratorNode(std::move(name)),
        condition_(std::move(condition)),
        otherwise_(otherwise),
        board_(board) {}

 private:
  Status onTick() override;

  Script condition_;
  Status otherwise_;
  Blackboard& board_;
};

}  // namespace roomba_rrt::bt
