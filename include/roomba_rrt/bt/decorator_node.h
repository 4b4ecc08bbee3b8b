// The base class of nodes with exactly one child (Inverter, Repeat, Retry, Timeout).
#pragma once

#include <memory>

#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// A node that owns one child and changes how its result (or its lifetime) is reported.
class DecoratorNode : public TreeNode {
 public:
  using TreeNode::TreeNode;

  void setChild(std::unique_ptr<TreeNode> child) { child_ = std::move(child); }
  TreeNode& child() { return *child_; }

 protected:
  /// Default halt: halt the child if it is running.
  void onHalt() override { child_->halt(); }

  std::unique_ptr<TreeNode> child_;
};

}  // namespace roomba_rrt::bt
