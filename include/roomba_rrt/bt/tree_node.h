// The base class of every behavior-tree node: leaves, decorators and control nodes.
#pragma once

#include <cstdint>
#include <string>

#include "roomba_rrt/bt/status.h"

namespace roomba_rrt::bt {

/// A node of a behavior tree.
///
/// Parents call the two non-virtual wrappers, node authors implement the protected hooks:
///
/// - tick(): if the node is not running (its first tick, or the first tick after it finished or
///   was halted) it is *entered* first (onEnter()); then it is *executed* (onTick()). The node is
///   running afterwards exactly when onTick() returned kRunning.
/// - halt(): stops a running node: onHalt() (a composite halts its running child there), then the
///   node is no longer running, so its next tick enters it anew. Halting a node that is not
///   running does nothing.
///
/// The wrappers cost one branch and a virtual call: no clock, lock, allocation or std::function
/// per tick, so a tree of a dozen nodes ticks in a few nanoseconds.
class TreeNode {
 public:
  explicit TreeNode(std::string name) : name_(std::move(name)) {}
  virtual ~TreeNode() = default;
  TreeNode(const TreeNode&) = delete;
  TreeNode& operator=(const TreeNode&) = delete;

  /// Enters the node if it is not running, then executes it once.
  Status tick() {
    if (!running_) onEnter();
    const Status status = onTick();
    running_ = status == Status::kRunning;
    last_status_ = status;
    ++ticks_;
    return status;
  }

  /// Stops the node if it is running (see the class comment).
  void halt() {
    if (!running_) return;
    onHalt();
    running_ = false;
  }

  bool isRunning() const { return running_; }
  /// The instance name (from the tree file's `name` attribute, or the node type).
  const std::string& name() const { return name_; }

  // For monitors (bt/tree_monitor.h: Groot2, ~tree_status), which look between ticks.
  /// What the last tick returned (meaningless while ticks() is 0).
  Status lastStatus() const { return last_status_; }
  /// How many times the node was ticked (wraps around; monitors compare it for a change).
  std::uint32_t ticks() const { return ticks_; }
  /// The node type it was built as (the tree file's element, e.g. "Sequence"; the factory sets
  /// it), or its name when it was built in code.
  const std::string& typeName() const { return type_name_.empty() ? name_ : type_name_; }
  void setTypeName(std::string type) { type_name_ = std::move(type); }

 protected:
  /// Called on the first tick after a (re)start, right before onTick().
  virtual void onEnter() {}
  /// One execution step; must return one of the three statuses.
  virtual Status onTick() = 0;
  /// Called by halt() while the node is running; release what the node holds.
  virtual void onHalt() {}

 private:
  std::string name_;
  std::string type_name_;
  bool running_ = false;
  Status last_status_ = Status::kFailure;
  std::uint32_t ticks_ = 0;
};

/// A leaf: an action or a condition written by the user (no children).
class LeafNode : public TreeNode {
 public:
  using TreeNode::TreeNode;
};

/// A leaf that only looks (HasGoal, IsBumped): it answers SUCCESS or FAILURE and commands
/// nothing. It ticks like any leaf; the tree factory registers it as a Condition, which is how
/// BehaviorTree.CPP's tools (Groot2) draw it.
class ConditionNode : public LeafNode {
 public:
  using LeafNode::LeafNode;
};

}  // namespace roomba_rrt::bt
