// Script and ScriptCondition (BehaviorTree.CPP): a leaf that runs a script (script.h).
#pragma once

#include <string>

#include "roomba_rrt/bt/ports.h"
#include "roomba_rrt/bt/script.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// Runs `code` (assignments such as `count := count + 1`) and returns SUCCESS; FAILURE when it
/// cannot be evaluated (BT.CPP throws instead).
class ScriptNode final : public LeafNode {
 public:
  static PortList providedPorts() { return {inputPort<std::string>("code", "the script to run")}; }
  /// `board` (the tree's blackboard) must outlive the node.
  ScriptNode(std::string name, Script script, Blackboard& board)
      : LeafNode(std::move(name)), script_(std::move(script)), board_(board) {}

 private:
  Status onTick() override;

  Script script_;
  Blackboard& board_;
};

/// Returns SUCCESS when `code` is true (a true boolean, a number that is not 0), FAILURE when it
/// is false or cannot be evaluated.
class ScriptCondition final : public ConditionNode {
 public:
  static PortList providedPorts() {
    return {inputPort<std::string>("code", "the condition, e.g. battery > 20")};
  }
  ScriptCondition(std::string name, Script script, Blackboard& board)
      : ConditionNode(std::move(name)), script_(std::move(script)), board_(board) {}

 private:
  Status onTick() override;

  Script script_;
  Blackboard& board_;
};

}  // namespace roomba_rrt::bt
