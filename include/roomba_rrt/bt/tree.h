// A behavior tree: the root node and everything below it.
#pragma once

#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/bt_file_logger.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// Owns a tree of nodes and ticks its root.
///
/// When the root returns SUCCESS or FAILURE it is no longer running, so the next tick enters it
/// anew and the tree starts again from the left (as in BehaviorTree.CPP). In the tick in which the
/// root finishes, the leaf that finished produced no action and no other leaf ran: a caller that
/// needs an output on every tick must say what that tick means (RoombaBt commands zero velocity).
class Tree {
 public:
  explicit Tree(std::unique_ptr<TreeNode> root, std::shared_ptr<Blackboard> blackboard = nullptr)
      : blackboard_(blackboard ? std::move(blackboard) : std::make_shared<Blackboard>()),
        root_(std::move(root)) {
    if (!root_) throw std::invalid_argument("bt::Tree: the root node is null");
  }

  /// Advances the blackboard's tick clock, then ticks the root.
  Status tick() {
    blackboard_->advanceTick();
    return root_->tick();
  }
  /// Halts every running node (e.g. when the robot is stopped from outside).
  void halt() { root_->halt(); }
  TreeNode& root() { return *root_; }
  /// The blackboard the tree's ports read and write.
  Blackboard& blackboard() { return *blackboard_; }

  /// Records the tree into `out` as a .btlog from now on (BtFileLogger: `tree_id`, the nodes
  /// model for Groot2, the clock); replaces a log in progress. The tree owns the stream.
  void startLog(std::unique_ptr<std::ostream> out, const std::string& tree_id,
                const std::string& nodes_model = "", BtFileLogger::Clock clock = nullptr) {
    logger_.reset();
    log_stream_ = std::move(out);
    logger_ =
        std::make_unique<BtFileLogger>(*this, *log_stream_, tree_id, nodes_model, std::move(clock));
  }
  /// Ends the log (flushed; the stream closed).
  void stopLog() {
    logger_.reset();
    log_stream_.reset();
  }
  /// The log in progress, or nullptr.
  const BtFileLogger* logger() const { return logger_.get(); }

 private:
  // The nodes point into the blackboard: it is destroyed after them.
  std::shared_ptr<Blackboard> blackboard_;
  std::unique_ptr<TreeNode> root_;
  // The logger observes the nodes: destroyed first, then its stream.
  std::unique_ptr<std::ostream> log_stream_;
  std::unique_ptr<BtFileLogger> logger_;
};

}  // namespace roomba_rrt::bt
