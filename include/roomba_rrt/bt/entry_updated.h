// WasEntryUpdated, SkipUnlessUpdated and WaitValueUpdate (BehaviorTree.CPP): react to a
// blackboard key being written since the node last looked.
#pragma once

#include <cstdint>
#include <string>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/decorator_node.h"

namespace roomba_rrt::bt {

/// How many times `key` was written (Blackboard::EntryBase::writes), 0 if it does not exist.
std::uint64_t writesOf(const Blackboard& board, const std::string& key);

/// WasEntryUpdated: SUCCESS when key `entry` was written since this node's previous tick (or,
/// on its first tick, ever), else FAILURE.
class WasEntryUpdated final : public ConditionNode {
 public:
  WasEntryUpdated(std::string name, std::string key, const Blackboard& board)
      : ConditionNode(std::move(name)), key_(std::move(key)), board_(board) {}

 private:
  Status onTick() override;

  std::string key_;
  const Blackboard& board_;
  std::uint64_t seen_ = 0;  ///< the write count at the previous tick
};

/// SkipUnlessUpdated (`if_not_updated` SKIPPED) and WaitValueUpdate (RUNNING): when the child is
/// not running, ticks it only if key `entry` was written since the node last looked, else
/// returns `if_not_updated`; a running child is ticked until it finishes, and its status
/// returned.
class EntryUpdatedDecorator final : public DecoratorNode {
 public:
  EntryUpdatedDecorator(std::string name, std::string key, const Blackboard& board,
                        Status if_not_updated)
      : DecoratorNode(std::move(name)),
        key_(std::move(key)),
        board_(board),
        if_not_updated_(if_not_updated) {}

 private:
  Status onTick() override;

  std::string key_;
  const Blackboard& board_;
  Status if_not_updated_;
  std::uint64_t seen_ = 0;  ///< the write count when it last looked
};

}  // namespace roomba_rrt::bt
