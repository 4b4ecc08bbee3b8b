#include "roomba_rrt/bt/tree_monitor.h"

#include <tinyxml2.h>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/decorator_node.h"

namespace roomba_rrt::bt {
namespace {

/// The children of `node`: a control node's, a decorator's one, none for a leaf.
std::vector<const TreeNode*> childrenOf(const TreeNode& node) {
  std::vector<const TreeNode*> children;
  // The accessors are not const (parents tick their children); the monitor only reads.
  auto& mutable_node = const_cast<TreeNode&>(node);
  if (auto* control = dynamic_cast<ControlNode*>(&mutable_node)) {
    for (std::size_t i = 0; i < control->childCount(); ++i) children.push_back(&control->child(i));
  } else if (auto* decorator = dynamic_cast<DecoratorNode*>(&mutable_node)) {
    children.push_back(&decorator->child());
  }
  return children;
}

void walk(const TreeNode& node, int parent, int depth, std::vector<MonitoredNode>& out) {
  const int index = static_cast<int>(out.size());
  MonitoredNode entry;
  entry.uid = static_cast<std::uint16_t>(index + 1);
  entry.parent = parent;
  entry.depth = depth;
  entry.type = node.typeName();
  entry.name = node.name();
  entry.path = parent < 0 ? node.name() : out[parent].path + "/" + node.name();
  entry.node = &node;
  out.push_back(entry);
  for (const TreeNode* child : childrenOf(node)) walk(*child, index, depth + 1, out);
  out[index].end = static_cast<int>(out.size());
}

MonitorStatus fromStatus(Status status) {
  switch (status) {
    case Status::kRunning:
      return MonitorStatus::kRunning;
    case Status::kSuccess:
      return MonitorStatus::kSuccess;
    case Status::kFailure:
      return MonitorStatus::kFailure;
    default:
      // The one other status BT.CPP has: a node skipped by its pre-condition.
      return MonitorStatus::kSkipped;
  }
}

/// What an active status becomes when the node's parent resets it (unchanged when idle already).
MonitorStatus idled(MonitorStatus status) {
  switch (status) {
    case MonitorStatus::kRunning:
      return MonitorStatus::kIdleFromRunning;
    case MonitorStatus::kSuccess:
      return MonitorStatus::kIdleFromSuccess;
    case MonitorStatus::kFailure:
      return MonitorStatus::kIdleFromFailure;
    case MonitorStatus::kSkipped:
      return MonitorStatus::kIdleFromSkipped;
    default:
      return status;
  }
}

}  // namespace

const char* toString(MonitorStatus status) {
  switch (status) {
    case MonitorStatus::kIdle:
      return "IDLE";
    case MonitorStatus::kRunning:
      return "RUNNING";
    case MonitorStatus::kSuccess:
      return "SUCCESS";
    case MonitorStatus::kFailure:
      return "FAILURE";
    case MonitorStatus::kIdleFromRunning:
      return "IDLE_FROM_RUNNING";
    case MonitorStatus::kIdleFromSuccess:
      return "IDLE_FROM_SUCCESS";
    case MonitorStatus::kIdleFromFailure:
      return "IDLE_FROM_FAILURE";
    case MonitorStatus::kSkipped:
      return "SKIPPED";
    case MonitorStatus::kIdleFromSkipped:
      return "IDLE_FROM_SKIPPED";
  }
  return "?";
}

TreeMonitor::TreeMonitor(const TreeNode& root) {
  walk(root, -1, 0, nodes_);
  status_.assign(nodes_.size(), MonitorStatus::kIdle);
  seen_ticks_.reserve(nodes_.size());
  for (const MonitoredNode& n : nodes_) seen_ticks_.push_back(n.node->ticks());
}

bool TreeMonitor::update() {
  bool changed = false;
  const auto set = [&](std::size_t i, MonitorStatus s) {
    changed = changed || status_[i] != s;
    status_[i] = s;
  };
  // 1. What each node did: ticked since the last look (its result), or halted while running.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const TreeNode& node = *nodes_[i].node;
    if (node.ticks() != seen_ticks_[i]) {
      seen_ticks_[i] = node.ticks();
      set(i, fromStatus(node.lastStatus()));
    } else if (status_[i] == MonitorStatus::kRunning && !node.isRunning()) {
      set(i, MonitorStatus::kIdleFromRunning);
    }
  }
  // 2. A node that is not running has reset its descendants: they show idle.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (status_[i] == MonitorStatus::kRunning) continue;
    const auto end = static_cast<std::size_t>(nodes_[i].end);
    for (std::size_t j = i + 1; j < end; ++j) set(j, idled(status_[j]));
    i = end - 1;
  }
  return changed;
}

std::vector<double> treeColumns(const TreeMonitor& monitor) {
  const auto& nodes = monitor.nodes();
  std::vector<double> column(nodes.size(), 0.0);
  std::vector<int> last_child(nodes.size(), -1);
  double next_leaf = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].parent >= 0) last_child[nodes[i].parent] = static_cast<int>(i);
    if (nodes[i].end == static_cast<int>(i) + 1) column[i] = next_leaf++;
  }
  for (std::size_t i = nodes.size(); i-- > 0;) {  // children before their parent
    if (last_child[i] >= 0) column[i] = (column[i + 1] + column[last_child[i]]) / 2;
  }
  return column;
}

std::string treeXmlWithUids(const TreeMonitor& monitor, const std::string& tree_id,
                            const std::string& model_xml) {
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* root = doc.NewElement("root");
  root->SetAttribute("BTCPP_format", "4");
  doc.InsertFirstChild(root);
  tinyxml2::XMLElement* tree = doc.NewElement("BehaviorTree");
  tree->SetAttribute("ID", tree_id.c_str());
  tree->SetAttribute("_fullpath", "");
  root->InsertEndChild(tree);

  std::vector<tinyxml2::XMLElement*> elements;
  for (const MonitoredNode& n : monitor.nodes()) {
    tinyxml2::XMLElement* e = doc.NewElement(n.type.c_str());
    e->SetAttribute("name", n.name.c_str());
    e->SetAttribute("_uid", n.uid);
    (n.parent < 0 ? tree : elements[n.parent])->InsertEndChild(e);
    elements.push_back(e);
  }

  tinyxml2::XMLDocument model;
  if (!model_xml.empty() && model.Parse(model_xml.c_str()) == tinyxml2::XML_SUCCESS) {
    const tinyxml2::XMLElement* model_root = model.FirstChildElement("root");
    const tinyxml2::XMLElement* nodes_model =
        model_root ? model_root->FirstChildElement("TreeNodesModel") : nullptr;
    if (nodes_model) root->InsertEndChild(nodes_model->DeepClone(&doc));
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

std::string mainTreeId(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS) return "MainTree";
  const tinyxml2::XMLElement* root = doc.FirstChildElement("root");
  if (!root) return "MainTree";
  if (const char* main = root->Attribute("main_tree_to_execute")) return main;
  const tinyxml2::XMLElement* tree = root->FirstChildElement("BehaviorTree");
  const char* id = tree ? tree->Attribute("ID") : nullptr;
  return id ? id : "MainTree";
}

}  // namespace roomba_rrt::bt
