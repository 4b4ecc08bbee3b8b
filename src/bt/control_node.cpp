#include "roomba_rrt/bt/control_node.h"

#include <stdexcept>

namespace roomba_rrt::bt {

void ControlNode::addChild(std::unique_ptr<TreeNode> child) {
  if (!child) throw std::invalid_argument(name() + ": a child is null");
  children_.push_back(std::move(child));
}

std::string ControlNode::childCountProblem(std::size_t children) const {
  if (requiredChildren() == 0 || children == requiredChildren()) return "";
  return "needs exactly " + std::to_string(requiredChildren()) + " children, got " +
         std::to_string(children);
}

void ControlNode::haltChildren(std::size_t first) {
  for (std::size_t i = first; i < children_.size(); ++i) children_[i]->halt();
}

}  // namespace roomba_rrt::bt
