// AlwaysSuccess and AlwaysFailure (BehaviorTree.CPP's actions): a leaf that answers one status.
#pragma once

#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// Returns `kResult` (SUCCESS or FAILURE) on every tick and does nothing else: a placeholder
/// while a tree is drafted, or the constant branch of a Fallback.
template <Status kResult>
class AlwaysStatus final : public LeafNode {
  static_assert(kResult != Status::kRunning, "AlwaysStatus answers SUCCESS or FAILURE");

 public:
  using LeafNode::LeafNode;

 private:
  Status onTick() override { return kResult; }
};

using AlwaysSuccess = AlwaysStatus<Status::kSuccess>;
using AlwaysFailure = AlwaysStatus<Status::kFailure>;

}  // namespace roomba_rrt::bt
