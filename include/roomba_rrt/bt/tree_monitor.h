// Watching a tree think: every node's status after each tick, as BehaviorTree.CPP's monitors
// (Groot2, its loggers) report it, for roomba_bt's Groot2 server and ~tree_status.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "roomba_rrt/bt/tree_node.h"

namespace roomba_rrt::bt {

/// A node's status as BehaviorTree.CPP's NodeStatus numbers it (what Groot2 reads), with Groot2's
/// encoding of a node that went back to idle: 10 + the status it had before.
enum class MonitorStatus : std::uint8_t {
  kIdle = 0,  ///< not ticked since the tree started
  kRunning = 1,
  kSuccess = 2,
  kFailure = 3,
  kSkipped = 4,           ///< BT.CPP's SKIPPED: a pre-condition (_skipIf) skipped the node
  kIdleFromRunning = 11,  ///< halted while running
  kIdleFromSuccess = 12,  ///< succeeded, then its parent finished or was halted
  kIdleFromFailure = 13,  ///< failed, then its parent finished or was halted
  kIdleFromSkipped = 14,  ///< skipped, then its parent finished or was halted
};

/// "IDLE", "RUNNING", "SUCCESS", "FAILURE", "IDLE_FROM_RUNNING", ...
const char* toString(MonitorStatus status);

/// One node of the tree, in preorder (a parent before its children, children left to right).
struct MonitoredNode {
  std::uint16_t uid = 0;  ///< 1, 2, ... in preorder (BehaviorTree.CPP numbers nodes from 1)
  int parent = -1;        ///< index of the parent in TreeMonitor::nodes(), -1 for the root
  int depth = 0;          ///< 0 for the root
  int end = 0;            ///< one past the index of its last descendant
  std::string type;       ///< TreeNode::typeName() ("Sequence", "MoveForward")
  std::string name;       ///< instance name
  std::string path;       ///< names from the root, joined by '/' ("Roomba/clean/MoveForward")
  const TreeNode* node = nullptr;
};

/// Follows the statuses of a tree's nodes from outside, ticks apart, as BehaviorTree.CPP shows
/// them: a node shows what its last tick returned (RUNNING, SUCCESS, FAILURE) until its parent
/// finishes or is halted, then idle (kIdleFrom*, as BehaviorTree.CPP's composites reset their
/// children when they finish); a node halted while running shows kIdleFromRunning; a node never
/// ticked shows kIdle. The root keeps its result until it is ticked again.
///
/// It reads TreeNode::ticks(), lastStatus() and isRunning() and changes nothing, so a tree ticks
/// the same with or without a monitor. Call update() after every tick (or group of ticks: a node
/// ticked several times in between shows its last result). Not synchronized: call it from the
/// thread that ticks the tree.
class TreeMonitor {
 public:
  /// Walks the tree below `root` (control nodes' and decorators' children); the tree must outlive
  /// the monitor and keep its shape (our trees do: nodes are built once).
  explicit TreeMonitor(const TreeNode& root);

  /// Looks at every node; true when a status changed since the last update().
  bool update();

  const std::vector<MonitoredNode>& nodes() const { return nodes_; }
  const std::vector<MonitorStatus>& statuses() const { return status_; }

 private:
  std::vector<MonitoredNode> nodes_;
  std::vector<MonitorStatus> status_;
  std::vector<std::uint32_t> seen_ticks_;  ///< each node's ticks() at the last update()
};

/// Where to draw each node of a tree diagram, in the monitor's order: the column (leaves 0, 1, 2,
/// ... from left to right; a parent centred over its first and last child); its row is its depth.
std::vector<double> treeColumns(const TreeMonitor& monitor);

/// The tree as BehaviorTree.CPP's WriteTreeToXML(tree, add_metadata=true) writes it, what Groot2
/// asks for: `<root BTCPP_format="4">`, one `<BehaviorTree ID="tree_id">` holding every node as
/// `<Type name="..." _uid="..."/>` (SubTrees appear expanded: our trees are built flat), then
/// the <TreeNodesModel> of `model_xml` (a document such as TreeFactory::treeNodesModel() writes;
/// "" for none).
std::string treeXmlWithUids(const TreeMonitor& monitor, const std::string& tree_id,
                            const std::string& model_xml);

/// The ID of the tree a tree file runs: its main_tree_to_execute, or its only <BehaviorTree>'s ID
/// ("MainTree" when the file has none or cannot be read: the tree factory reports those).
std::string mainTreeId(const std::string& xml);

}  // namespace roomba_rrt::bt
