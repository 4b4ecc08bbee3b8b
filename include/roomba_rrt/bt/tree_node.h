// The base class of every behavior-tree node: leaves, decorators and control nodes.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "roomba_rrt/bt/status.h"

namespace roomba_rrt::bt {

struct NodeConditions;
class TreeNode;

/// Told of every status a node returns and of every halt: a logger (bt_file_logger.h) or a
/// monitor. Opt-in per node (TreeNode::setObserver); a node without one (and without
/// conditions) pays one predictable branch per tick for the possibility.
class TreeObserver {
 public:
  virtual ~TreeObserver() = default;
  /// `node` returned `status` from tick().
  virtual void onStatus(const TreeNode& node, Status status) = 0;
  /// `node` was halted while running.
  virtual void onHalted(const TreeNode& node) = 0;
};

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
/// The wrappers cost two branches and a virtual call: no clock, lock, allocation or std::function
/// per tick, so a tree of a dozen nodes ticks in a few nanoseconds.
class TreeNode {
 public:
  explicit TreeNode(std::string name) : name_(std::move(name)) {}
  virtual ~TreeNode() = default;
  TreeNode(const TreeNode&) = delete;
  TreeNode& operator=(const TreeNode&) = delete;

  /// Enters the node if it is not running, then executes it once. A node with pre/post-condition
  /// scripts (node_conditions.h) checks and runs them around that.
  Status tick() {
    if (!plain_) return tickWithExtras();
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
    if (!plain_) afterHalt();
  }

  bool isRunning() const { return running_; }
  /// The instance name (from the tree file's `name` attribute, or the node type).
  const std::string& name() const { return name_; }
  /// Gives the node pre/post-condition scripts (the tree factory does, for `_successIf` & co).
  bool hasConditions() const { return conditions_ != nullptr; }
  void setConditions(std::shared_ptr<const NodeConditions> conditions) {
    conditions_ = std::move(conditions);
    plain_ = !conditions_ && !observer_;
  }
  /// Reports this node's statuses and halts to `observer` (nullptr: to nobody), which must
  /// outlive the node or be taken off first.
  void setObserver(TreeObserver* observer) {
    observer_ = observer;
    plain_ = !conditions_ && !observer_;
  }
  /// The node type it was built as (the tree file's element, e.g. "Sequence"; the factory sets
  /// it), or its name when it was built in code.
  const std::string& typeName() const { return type_name_.empty() ? name_ : type_name_; }
  void setTypeName(std::string type) { type_name_ = std::move(type); }

  // For monitors (bt/tree_monitor.h: Groot2, ~tree_status), which look between ticks.
  /// What the last tick returned (meaningless while ticks() is 0).
  Status lastStatus() const { return last_status_; }
  /// How many times the node was ticked (wraps around; monitors compare it for a change).
  std::uint32_t ticks() const { return ticks_; }

 protected:
  /// Called on the first tick after a (re)start, right before onTick().
  virtual void onEnter() {}
  /// One execution step; must return one of the three statuses.
  virtual Status onTick() = 0;
  /// Called by halt() while the node is running; release what the node holds.
  virtual void onHalt() {}

 private:
  /// tick() and halt() with conditions and an observer (src/bt/tree_node.cpp).
  Status tickWithExtras();
  void afterHalt();

  std::string name_;
  std::string type_name_;
  bool running_ = false;
  Status last_status_ = Status::kFailure;
  std::uint32_t ticks_ = 0;
  bool plain_ = true;  ///< no conditions and no observer: tick() takes the short path
  std::shared_ptr<const NodeConditions> conditions_;
  TreeObserver* observer_ = nullptr;
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
