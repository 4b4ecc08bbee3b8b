#include "roomba_rrt/bt/bt_file_logger.h"

#include <tinyxml2.h>

#include <chrono>
#include <stdexcept>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/tree.h"

namespace roomba_rrt::bt {
namespace {

/// The children of `node` (none for a leaf).
std::vector<TreeNode*> childrenOf(TreeNode& node) {
  std::vector<TreeNode*> children;
  if (auto* control = dynamic_cast<ControlNode*>(&node)) {
    for (std::size_t i = 0; i < control->childCount(); ++i) children.push_back(&control->child(i));
  } else if (auto* decorator = dynamic_cast<DecoratorNode*>(&node)) {
    children.push_back(&decorator->child());
  }
  return children;
}

void collect(TreeNode& node, std::vector<TreeNode*>& out) {
  out.push_back(&node);
  for (TreeNode* child : childrenOf(node)) collect(*child, out);
}

void writeNode(TreeNode& node, unsigned& uid, tinyxml2::XMLPrinter& out) {
  out.OpenElement(node.typeName().c_str());
  if (node.name() != node.typeName()) out.PushAttribute("name", node.name().c_str());
  out.PushAttribute("_uid", ++uid);
  for (TreeNode* child : childrenOf(node)) writeNode(*child, uid, out);
  out.CloseElement();
}

std::int64_t systemMicroseconds() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

LogStatus logStatus(Status status) {
  switch (status) {
    case Status::kSuccess:
      return LogStatus::kSuccess;
    case Status::kFailure:
      return LogStatus::kFailure;
    case Status::kRunning:
      return LogStatus::kRunning;
    case Status::kSkipped:  // BT.CPP keeps a skipped node IDLE
      return LogStatus::kIdle;
  }
  return LogStatus::kIdle;
}

}  // namespace

std::vector<TreeNode*> uidsOf(TreeNode& root) {
  std::vector<TreeNode*> nodes;
  collect(root, nodes);
  return nodes;
}

std::string treeXmlWithUids(TreeNode& root, const std::string& tree_id,
                            const std::string& nodes_model) {
  tinyxml2::XMLPrinter out;
  out.OpenElement("root");
  out.PushAttribute("BTCPP_format", "4");
  out.PushAttribute("main_tree_to_execute", tree_id.c_str());
  out.OpenElement("BehaviorTree");
  out.PushAttribute("ID", tree_id.c_str());
  unsigned uid = 0;
  writeNode(root, uid, out);
  out.CloseElement();
  tinyxml2::XMLDocument model;
  if (!nodes_model.empty() && model.Parse(nodes_model.c_str()) == tinyxml2::XML_SUCCESS &&
      model.RootElement()) {
    if (const auto* element = model.RootElement()->FirstChildElement("TreeNodesModel")) {
      element->Accept(&out);
    }
  }
  out.CloseElement();
  return out.CStr();
}

BtFileLogger::BtFileLogger(Tree& tree, std::ostream& out, const std::string& tree_id,
                           const std::string& nodes_model, Clock clock)
    : nodes_(uidsOf(tree.root())),
      out_(out),
      clock_(clock ? std::move(clock) : Clock(systemMicroseconds)),
      start_usec_(clock_()),
      writer_(out, treeXmlWithUids(tree.root(), tree_id, nodes_model), start_usec_) {
  if (nodes_.size() > 65535) {
    throw std::invalid_argument("a .btlog names at most 65535 nodes, the tree has " +
                                std::to_string(nodes_.size()));
  }
  status_.assign(nodes_.size(), LogStatus::kIdle);
  subtree_end_.resize(nodes_.size());
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    std::size_t end = i + 1;
    for (TreeNode* child : childrenOf(*nodes_[i])) {
      (void)child;
      end = subtree_end_[end];  // each child's subtree follows the previous one
    }
    subtree_end_[i] = end;
    index_[nodes_[i]] = i;
  }
  for (TreeNode* node : nodes_) node->setObserver(this);
}

BtFileLogger::~BtFileLogger() {
  for (TreeNode* node : nodes_) node->setObserver(nullptr);
  out_.flush();
}

void BtFileLogger::record(std::size_t index, LogStatus status) {
  if (status_[index] == status) return;
  status_[index] = status;
  const std::int64_t now = clock_();
  writer_.write({static_cast<std::uint64_t>(now > start_usec_ ? now - start_usec_ : 0),
                 static_cast<std::uint16_t>(index + 1), status});
  ++transitions_;
}

void BtFileLogger::resetBelow(std::size_t index) {
  for (std::size_t i = index + 1; i < subtree_end_[index]; ++i) record(i, LogStatus::kIdle);
}

void BtFileLogger::onStatus(const TreeNode& node, Status status) {
  const std::size_t index = index_.at(&node);
  if (status != Status::kRunning) resetBelow(index);
  record(index, logStatus(status));
}

void BtFileLogger::onHalted(const TreeNode& node) {
  const std::size_t index = index_.at(&node);
  resetBelow(index);
  record(index, LogStatus::kIdle);
}

}  // namespace roomba_rrt::bt
