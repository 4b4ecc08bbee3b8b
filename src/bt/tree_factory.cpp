#include "roomba_rrt/bt/tree_factory.h"

#include <tinyxml2.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/inverter_node.h"
#include "roomba_rrt/bt/reactive_selector.h"
#include "roomba_rrt/bt/reactive_sequence.h"
#include "roomba_rrt/bt/repeat_node.h"
#include "roomba_rrt/bt/retry_node.h"
#include "roomba_rrt/bt/selector_node.h"
#include "roomba_rrt/bt/sequence_node.h"
#include "roomba_rrt/bt/timeout_node.h"

namespace roomba_rrt::bt {
namespace {

using tinyxml2::XMLElement;

int childElementCount(const XMLElement& element) {
  int count = 0;
  for (const XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement()) ++count;
  return count;
}

/// A builder for node types whose only argument is the instance name.
template <class Node>
TreeFactory::Builder namedBuilder() {
  return [](const NodeSpec& spec) { return std::make_unique<Node>(spec.name); };
}

[[noreturn]] void fail(const std::string& source, const XMLElement& element,
                       const std::string& message) {
  throw TreeFileError(source, element.GetLineNum(),
                      "<" + std::string(element.Name()) + ">: " + message);
}

}  // namespace

TreeFileError::TreeFileError(const std::string& source, int line, const std::string& message)
    : std::runtime_error(source + ":" + std::to_string(line) + ": " + message), line_(line) {}

long NodeSpec::integer(const std::string& key) const {
  const auto it = attributes.find(key);
  if (it == attributes.end()) throw std::invalid_argument("missing attribute '" + key + "'");
  std::size_t used = 0;
  long value = 0;
  try {
    value = std::stol(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != it->second.size()) {
    throw std::invalid_argument("attribute '" + key + "' must be an integer, got '" + it->second +
                                "'");
  }
  return value;
}

TreeFactory::TreeFactory() {
  registerNode("Sequence", NodeKind::kControl, namedBuilder<SequenceNode>());
  registerNode("Selector", NodeKind::kControl, namedBuilder<SelectorNode>());
  registerNode("Fallback", NodeKind::kControl, namedBuilder<SelectorNode>());
  registerNode("ReactiveSequence", NodeKind::kControl, namedBuilder<ReactiveSequence>());
  registerNode("ReactiveSelector", NodeKind::kControl, namedBuilder<ReactiveSelector>());
  registerNode("ReactiveFallback", NodeKind::kControl, namedBuilder<ReactiveSelector>());
  registerNode("Inverter", NodeKind::kDecorator, namedBuilder<InverterNode>());
  registerNode("Repeat", NodeKind::kDecorator,
               [](const NodeSpec& s) {
                 return std::make_unique<RepeatNode>(s.name,
                                                     static_cast<int>(s.integer("num_cycles")));
               },
               {"num_cycles"});
  registerNode("Retry", NodeKind::kDecorator,
               [](const NodeSpec& s) {
                 return std::make_unique<RetryNode>(s.name,
                                                    static_cast<int>(s.integer("num_attempts")));
               },
               {"num_attempts"});
  registerNode(
      "Timeout", NodeKind::kDecorator,
      [](const NodeSpec& s) { return std::make_unique<TimeoutNode>(s.name, s.integer("ticks")); },
      {"ticks"});
}

void TreeFactory::registerNode(const std::string& type, NodeKind kind, Builder builder,
                               std::vector<std::string> attributes) {
  if (!builder) throw std::invalid_argument("node type '" + type + "' has no builder");
  if (!entries_.emplace(type, Entry{kind, std::move(builder), std::move(attributes)}).second) {
    throw std::invalid_argument("node type '" + type + "' is already registered");
  }
}

void TreeFactory::registerLeaf(const std::string& type, Builder builder) {
  registerNode(type, NodeKind::kLeaf, std::move(builder));
}

std::vector<std::string> TreeFactory::types() const {
  std::vector<std::string> names;
  for (const auto& entry : entries_) names.push_back(entry.first);
  return names;
}

Tree TreeFactory::buildFromFile(const std::string& path) const {
  std::ifstream file(path);
  if (!file) throw TreeFileError(path, 0, "cannot open the tree file");
  std::stringstream text;
  text << file.rdbuf();
  return buildFromText(text.str(), path);
}

Tree TreeFactory::buildFromText(const std::string& xml, const std::string& source) const {
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw TreeFileError(source, document.ErrorLineNum(),
                        std::string("malformed XML: ") + document.ErrorStr());
  }
  const XMLElement* root = document.RootElement();
  const auto bad = [&](const XMLElement* e, const std::string& message) {
    return TreeFileError(source, e ? e->GetLineNum() : 0, message);
  };
  if (!root || std::string(root->Name()) != "root") {
    throw bad(root, "the document element must be <root>");
  }

  // Pick the <BehaviorTree> to build: the one named by main_tree_to_execute, or the only one.
  const char* main_id = root->Attribute("main_tree_to_execute");
  const XMLElement* chosen = nullptr;
  int trees = 0;
  for (const XMLElement* t = root->FirstChildElement("BehaviorTree"); t;
       t = t->NextSiblingElement("BehaviorTree")) {
    ++trees;
    const char* id = t->Attribute("ID");
    if (!main_id || (id && std::string(id) == main_id)) chosen = chosen ? chosen : t;
  }
  if (trees == 0) throw bad(root, "<root>: no <BehaviorTree> element");
  if (!main_id && trees > 1) {
    throw bad(root, "<root>: several <BehaviorTree> elements; name one in main_tree_to_execute");
  }
  if (!chosen) {
    throw bad(root, std::string("<root>: no <BehaviorTree ID=\"") + main_id + "\">");
  }
  if (childElementCount(*chosen) != 1) {
    throw bad(chosen, "<BehaviorTree>: needs exactly one root node, got " +
                          std::to_string(childElementCount(*chosen)));
  }

  return Tree(buildNode(*chosen->FirstChildElement(), source));
}

std::unique_ptr<TreeNode> TreeFactory::buildNode(const XMLElement& element,
                                                 const std::string& source) const {
  const auto entry = entries_.find(element.Name());
  if (entry == entries_.end()) fail(source, element, "unknown node type");
  const Entry& e = entry->second;

  NodeSpec spec;
  spec.type = element.Name();
  spec.name = spec.type;
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    if (key == "name") {
      spec.name = a->Value();
    } else if (std::find(e.attributes.begin(), e.attributes.end(), key) != e.attributes.end()) {
      spec.attributes[key] = a->Value();
    } else {
      fail(source, element, "unknown attribute '" + key + "'");
    }
  }

  const int children = childElementCount(element);
  if (e.kind == NodeKind::kLeaf && children > 0) {
    fail(source, element, "a leaf cannot have children");
  }
  if (e.kind == NodeKind::kControl && children == 0) {
    fail(source, element, "a control node needs at least one child");
  }
  if (e.kind == NodeKind::kDecorator && children != 1) {
    fail(source, element, "a decorator needs exactly one child, got " + std::to_string(children));
  }

  std::unique_ptr<TreeNode> node;
  try {
    node = e.builder(spec);
  } catch (const std::invalid_argument& error) {
    fail(source, element, error.what());
  }
  if (!node) fail(source, element, "the registered builder returned no node");

  for (const XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::unique_ptr<TreeNode> child = buildNode(*c, source);
    if (auto* control = dynamic_cast<ControlNode*>(node.get())) {
      control->addChild(std::move(child));
    } else if (auto* decorator = dynamic_cast<DecoratorNode*>(node.get())) {
      decorator->setChild(std::move(child));
    } else {
      fail(source, element, "registered with children but built as a leaf");
    }
  }
  return node;
}

}  // namespace roomba_rrt::bt
