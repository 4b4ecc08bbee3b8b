// SetBlackboard and UnsetBlackboard (BehaviorTree.CPP): write or forget a key from the tree file.
#pragma once

#include <optional>
#include <string>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// Writes `value` to key `output_key` and returns SUCCESS. `value` is a literal or `{key}`,
/// whose value is copied. A literal goes into an existing key as its type reads it ("3" into a
/// double, "true" into a bool) and creates a missing key as a string. Keys of the types scripts
/// know (bool, int, long, double, string). FAILURE when the value does not fit the key or the
/// source key was never written (BT.CPP throws instead).
class SetBlackboard final : public LeafNode {
 public:
  /// `source` is the key of a `{key}` value, or nothing for the literal `text`.
  SetBlackboard(std::string name, std::string output_key, std::optional<std::string> source,
                std::string text, Blackboard& board)
      : LeafNode(std::move(name)),
        output_key_(std::move(output_key)),
        source_(std::move(source)),
        text_(std::move(text)),
        board_(board) {}

 private:
  Status onTick() override;

  std::string output_key_;
  std::optional<std::string> source_;
  std::string text_;
  Blackboard& board_;
};

/// Forgets key `key`'s value (readers see nothing until it is written again) and returns
/// SUCCESS; a key the blackboard does not have is left alone.
class UnsetBlackboard final : public LeafNode {
 public:
  UnsetBlackboard(std::string name, std::string key, Blackboard& board)
      : LeafNode(std::move(name)), key_(std::move(key)), board_(board) {}

 private:
  Status onTick() override {
    if (Blackboard::EntryBase* entry = board_.find(key_)) entry->writes = 0;
    return Status::kSuccess;
  }

  std::string key_;
  Blackboard& board_;
};

}  // namespace roomba_rrt::bt
