// Recording a running tree as a .btlog (BehaviorTree.CPP's FileLogger2 format, bt_log.h), which
// Groot2 replays and `roomba_bt --print-log` prints.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "roomba_rrt/bt/bt_log.h"
#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

class Tree;

/// The tree below `root` as BehaviorTree.CPP writes it for Groot2 (WriteTreeToXML with
/// metadata): one <BehaviorTree ID="`tree_id`">, every node an element of its type name with
/// its `name` and a `_uid` (1, 2, ... in depth-first order, the order uidsOf() gives), and the
/// <TreeNodesModel> of `nodes_model` (TreeFactory::treeNodesModel(); "" for none). SubTrees
/// appear expanded, as the nodes they were built into.
std::string treeXmlWithUids(TreeNode& root, const std::string& tree_id,
                            const std::string& nodes_model = "");
/// The nodes below `root` in depth-first order: node i has `_uid` i + 1.
std::vector<TreeNode*> uidsOf(TreeNode& root);

/// Observes every node of a tree and writes each status change to a .btlog as BT.CPP's
/// FileLogger2 does, IDLE included: a node that finishes or is halted resets the nodes below it
/// to IDLE (BT.CPP's resetChildren), and a halted node goes IDLE itself.
///
/// Costs nothing while no logger is attached; attached, every node takes tick()'s slower path
/// and a status change costs a map lookup and a 9-byte write. The logger must be destroyed
/// before the tree (it takes its observers off the nodes); one tree, one logger.
class BtFileLogger final : public TreeObserver {
 public:
  /// Microseconds since the Unix epoch (the node passes ROS time, so a simulated run replays
  /// at its own pace; the default is the system clock).
  using Clock = std::function<std::int64_t()>;

  /// Writes the header to `out` (binary) at once. std::invalid_argument for a tree of more than
  /// 65535 nodes (the format's uid is 16 bits).
  BtFileLogger(Tree& tree, std::ostream& out, const std::string& tree_id,
               const std::string& nodes_model = "", Clock clock = nullptr);
  ~BtFileLogger() override;
  BtFileLogger(const BtFileLogger&) = delete;
  BtFileLogger& operator=(const BtFileLogger&) = delete;

  void onStatus(const TreeNode& node, Status status) override;
  void onHalted(const TreeNode& node) override;
  /// Transitions written so far.
  std::size_t transitions() const { return transitions_; }

 private:
  /// Records `uid`'s new status if it changed.
  void record(std::size_t index, LogStatus status);
  /// Every node below node `index` back to IDLE.
  void resetBelow(std::size_t index);

  std::vector<TreeNode*> nodes_;          ///< by uid - 1
  std::vector<std::size_t> subtree_end_;  ///< one past node i's last descendant
  std::map<const TreeNode*, std::size_t> index_;
  std::vector<LogStatus> status_;  ///< as last written
  std::ostream& out_;
  Clock clock_;
  std::int64_t start_usec_;  ///< the log's start time
  BtLogWriter writer_;
  std::size_t transitions_ = 0;
};

}  // namespace roomba_rrt::bt
