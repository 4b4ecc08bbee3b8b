// The base class of nodes with one or more children (Sequence, Selector and their reactive
// variants).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// A node that owns an ordered list of children and ticks them from left to right.
class ControlNode : public TreeNode {
 public:
  using TreeNode::TreeNode;

  /// Appends a child (the tree factory rejects composites left empty).
  void addChild(std::unique_ptr<TreeNode> child);
  std::size_t childCount() const { return children_.size(); }
  TreeNode& child(std::size_t i) { return *children_[i]; }
  /// How many children the node needs: 0 for "one or more" (the default), else exactly that
  /// many (the tree factory checks it).
  virtual std::size_t requiredChildren() const { return 0; }
  /// "" when the node works with `children` children, else what is wrong (the tree factory
  /// names it). The default checks requiredChildren(); nodes that take a range (IfThenElse: 2 or
  /// 3) or whose ports bound the count (Parallel's thresholds) override it.
  virtual std::string childCountProblem(std::size_t children) const;

 protected:
  /// Halts every running child from index `first` on (halting a child that is not running does
  /// nothing, so this is safe to call on all of them).
  void haltChildren(std::size_t first = 0);
  /// Default halt for every composite: halt the running children.
  void onHalt() override { haltChildren(); }

  std::vector<std::unique_ptr<TreeNode>> children_;
};

}  // namespace roomba_rrt::bt
