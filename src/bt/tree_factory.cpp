#include "roomba_rrt/bt/tree_factory.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "roomba_rrt/bt/inverter_node.h"
#include "roomba_rrt/bt/pipeline_sequence.h"
#include "roomba_rrt/bt/rate_controller.h"
#include "roomba_rrt/bt/reactive_selector.h"
#include "roomba_rrt/bt/reactive_sequence.h"
#include "roomba_rrt/bt/recovery_node.h"
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
  throw TreeFileError(source, element.GetLineNum(), "<" + std::string(element.Name()) + ">",
                      message);
}

/// "port 'goal' (Pose2D: the goal pose)" for messages.
std::string describe(const PortInfo& port) {
  return "port '" + port.name + "' (" + port.type_name +
         (port.description.empty() ? "" : ": " + port.description) + ")";
}

}  // namespace

/// What the build of one tree collects to check the blackboard keys at the end.
struct TreeFactory::BuildState {
  std::string source;
  Blackboard* blackboard = nullptr;
  std::set<std::string> declared_before;  ///< keys the application declared
  std::set<std::string> named;            ///< keys the tree file names
  std::set<std::string> written;          ///< keys some output port writes
  struct Read {
    std::string key;
    std::string port;
    const XMLElement* element;
  };
  std::vector<Read> reads;  ///< input ports bound to keys
  int nodes = 0;
};

TreeFileError::TreeFileError(const std::string& source, int line, const std::string& element,
                             const std::string& problem)
    : util::InvalidInput(element, problem, source + ":" + std::to_string(line)), line_(line) {}

const std::string& NodeSpec::text(const std::string& port) const {
  const auto it = attributes.find(port);
  if (it == attributes.end()) throw std::invalid_argument("missing port '" + port + "'");
  return it->second;
}

Blackboard& NodeSpec::board() const {
  if (!blackboard) throw std::invalid_argument("the node was built without a blackboard");
  return *blackboard;
}

TreeFactory::TreeFactory() {
  registerNode("Sequence", NodeKind::kControl, namedBuilder<SequenceNode>());
  registerNode("Selector", NodeKind::kControl, namedBuilder<SelectorNode>());
  registerNode("Fallback", NodeKind::kControl, namedBuilder<SelectorNode>());
  registerNode("ReactiveSequence", NodeKind::kControl, namedBuilder<ReactiveSequence>());
  registerNode("ReactiveSelector", NodeKind::kControl, namedBuilder<ReactiveSelector>());
  registerNode("ReactiveFallback", NodeKind::kControl, namedBuilder<ReactiveSelector>());
  registerNode("PipelineSequence", NodeKind::kControl, namedBuilder<PipelineSequence>());
  registerNodeType<RecoveryNode>("RecoveryNode", [](const NodeSpec& s) {
    return std::make_unique<RecoveryNode>(s.name, s.literal<int>("number_of_retries"));
  });
  registerNode("Inverter", NodeKind::kDecorator, namedBuilder<InverterNode>());
  registerNodeType<RepeatNode>("Repeat", [](const NodeSpec& s) {
    return std::make_unique<RepeatNode>(s.name, s.literal<int>("num_cycles"));
  });
  registerNodeType<RetryNode>("Retry", [](const NodeSpec& s) {
    return std::make_unique<RetryNode>(s.name, s.literal<int>("num_attempts"));
  });
  registerNodeType<TimeoutNode>("Timeout", [](const NodeSpec& s) {
    return std::make_unique<TimeoutNode>(s.name, s.literal<long>("ticks"));
  });
  registerNodeType<RateController>("RateController", [](const NodeSpec& s) {
    return std::make_unique<RateController>(s.name, s.literal<double>("hz"), s.tick_rate,
                                            *s.blackboard);
  });
}

void TreeFactory::registerNode(const std::string& type, NodeKind kind, Builder builder,
                               std::vector<std::string> attributes) {
  PortList ports;
  for (auto& name : attributes) {
    PortInfo port;
    port.name = std::move(name);
    port.type_name = "string";
    port.default_value = std::nullopt;
    port.raw = true;
    ports.push_back(std::move(port));
  }
  registerNodeWithPorts(type, kind, std::move(builder), std::move(ports));
}

void TreeFactory::registerNodeWithPorts(const std::string& type, NodeKind kind, Builder builder,
                                        PortList ports) {
  if (!builder) throw std::invalid_argument("node type '" + type + "' has no builder");
  for (const PortInfo& port : ports) {
    if (port.name.empty() || port.name == "name") {
      throw std::invalid_argument("node type '" + type + "': invalid port name '" + port.name +
                                  "'");
    }
    if (!port.raw && (!port.declare || !port.check)) {
      throw std::invalid_argument("node type '" + type + "': port '" + port.name +
                                  "' was not made by inputPort() or outputPort()");
    }
  }
  if (!entries_.emplace(type, Entry{kind, std::move(builder), std::move(ports)}).second) {
    throw std::invalid_argument("node type '" + type + "' is already registered");
  }
}

void TreeFactory::registerLeaf(const std::string& type, Builder builder) {
  registerNode(type, NodeKind::kLeaf, std::move(builder));
}

void TreeFactory::setTickRate(double hz) {
  if (!(std::isfinite(hz) && hz > 0)) {
    throw util::InvalidInput("tick_rate", "must be finite and > 0, got " + util::show(hz));
  }
  tick_rate_ = hz;
}

const PortList& TreeFactory::ports(const std::string& type) const {
  const auto it = entries_.find(type);
  if (it == entries_.end()) throw std::invalid_argument("unknown node type '" + type + "'");
  return it->second.ports;
}

Tree TreeFactory::buildFromFile(const std::string& path) const {
  return buildFromFile(path, std::make_shared<Blackboard>());
}

Tree TreeFactory::buildFromText(const std::string& xml, const std::string& source) const {
  return buildFromText(xml, source, std::make_shared<Blackboard>());
}

Tree TreeFactory::buildFromFile(const std::string& path,
                                std::shared_ptr<Blackboard> blackboard) const {
  std::ifstream file(path);
  if (!file) throw TreeFileError(path, 0, "", "cannot open the tree file");
  std::stringstream text;
  text << file.rdbuf();
  if (file.bad()) throw TreeFileError(path, 0, "", "cannot read the tree file");
  return buildFromText(text.str(), path, std::move(blackboard));
}

Tree TreeFactory::buildFromText(const std::string& xml, const std::string& source,
                                std::shared_ptr<Blackboard> blackboard) const {
  if (!blackboard) throw std::invalid_argument("buildFromText: the blackboard is null");
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw TreeFileError(source, document.ErrorLineNum(), "",
                        std::string("malformed XML: ") + document.ErrorStr());
  }
  const XMLElement* root = document.RootElement();
  if (!root || std::string(root->Name()) != "root") {
    throw TreeFileError(source, root ? root->GetLineNum() : 0, "",
                        "the document element must be <root>");
  }

  // Pick the <BehaviorTree> to build: the one named by main_tree_to_execute, or the only one.
  const char* main_id = root->Attribute("main_tree_to_execute");
  const XMLElement* chosen = nullptr;
  int trees = 0;
  std::map<std::string, int> ids;  // ID -> line of its first <BehaviorTree>
  for (const XMLElement* t = root->FirstChildElement("BehaviorTree"); t;
       t = t->NextSiblingElement("BehaviorTree")) {
    ++trees;
    const char* id = t->Attribute("ID");
    if (id) {
      const auto [it, fresh] = ids.emplace(id, t->GetLineNum());
      if (!fresh) {
        fail(source, *t,
             std::string("ID \"") + id + "\" is used twice (first on line " +
                 std::to_string(it->second) + ")");
      }
    }
    if (!main_id || (id && std::string(id) == main_id)) chosen = chosen ? chosen : t;
  }
  if (trees == 0) fail(source, *root, "no <BehaviorTree> element");
  if (!main_id && trees > 1) {
    fail(source, *root, "several <BehaviorTree> elements; name one in main_tree_to_execute");
  }
  if (!chosen) fail(source, *root, std::string("no <BehaviorTree ID=\"") + main_id + "\">");
  if (childElementCount(*chosen) != 1) {
    fail(source, *chosen,
         "needs exactly one root node, got " + std::to_string(childElementCount(*chosen)));
  }

  BuildState state;
  state.source = source;
  state.blackboard = blackboard.get();
  // Keys the application declared count as written by it (it may write them between ticks).
  std::unique_ptr<TreeNode> node = buildNode(*chosen->FirstChildElement(), 1, state);
  for (const auto& read : state.reads) {
    if (state.written.count(read.key) == 0 && state.declared_before.count(read.key) == 0) {
      fail(source, *read.element,
           "port '" + read.port + "' reads blackboard key '" + read.key +
               "', which nothing writes (no output port of the tree names it and the "
               "application did not declare it)");
    }
  }
  return Tree(std::move(node), std::move(blackboard));
}

std::unique_ptr<TreeNode> TreeFactory::buildNode(const XMLElement& element, int depth,
                                                 BuildState& state) const {
  if (depth > kMaxDepth) {
    fail(state.source, element,
         "nesting deeper than " + std::to_string(kMaxDepth) + " nodes is not supported");
  }
  if (++state.nodes > kMaxNodes) {
    fail(state.source, element,
         "more than " + std::to_string(kMaxNodes) + " nodes in one tree is not supported");
  }
  const auto entry = entries_.find(element.Name());
  if (entry == entries_.end()) fail(state.source, element, "unknown node type");
  const Entry& e = entry->second;

  NodeSpec spec;
  spec.type = element.Name();
  spec.name = spec.type;
  spec.blackboard = state.blackboard;
  spec.ports = &e.ports;
  spec.tick_rate = tick_rate_;
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    if (key == "name") {
      spec.name = a->Value();
      continue;
    }
    const bool known = std::any_of(e.ports.begin(), e.ports.end(),
                                   [&](const PortInfo& p) { return p.name == key; });
    if (!known) fail(state.source, element, "unknown attribute '" + key + "'");
    spec.attributes[key] = a->Value();
  }

  // Ports: required ones present, literals valid, keys typed consistently.
  for (const PortInfo& port : e.ports) {
    if (port.raw) continue;
    auto it = spec.attributes.find(port.name);
    if (it == spec.attributes.end()) {
      if (port.required()) fail(state.source, element, "missing required " + describe(port));
      it = spec.attributes.emplace(port.name, *port.default_value).first;
    }
    std::string key;
    if (parseBlackboardKey(it->second, key)) {
      if (state.named.insert(key).second && state.blackboard->find(key)) {
        state.declared_before.insert(key);  // there before this tree named it
      }
      try {
        port.declare(*state.blackboard, key);
      } catch (const std::invalid_argument& error) {
        fail(state.source, element, describe(port) + ": " + error.what());
      }
      if (port.direction == PortDirection::kOutput) {
        state.written.insert(key);
      } else {
        state.reads.push_back({key, port.name, &element});
      }
    } else if (port.direction == PortDirection::kOutput) {
      fail(state.source, element,
           "output " + describe(port) + " needs a blackboard key like {" + port.name + "}, got '" +
               it->second + "'");
    } else {
      const std::string problem = port.check(port, it->second);
      if (!problem.empty()) {
        fail(state.source, element, "attribute '" + port.name + "' " + problem);
      }
    }
  }

  const int children = childElementCount(element);
  if (e.kind == NodeKind::kLeaf && children > 0) {
    fail(state.source, element, "a leaf cannot have children");
  }
  if (e.kind == NodeKind::kControl && children == 0) {
    fail(state.source, element, "a control node needs at least one child");
  }
  if (e.kind == NodeKind::kDecorator && children != 1) {
    fail(state.source, element,
         "a decorator needs exactly one child, got " + std::to_string(children));
  }

  std::unique_ptr<TreeNode> node;
  try {
    node = e.builder(spec);
  } catch (const std::invalid_argument& error) {
    fail(state.source, element, error.what());
  }
  if (!node) fail(state.source, element, "the registered builder returned no node");
  if (auto* control = dynamic_cast<ControlNode*>(node.get())) {
    const std::size_t needed = control->requiredChildren();
    if (needed != 0 && static_cast<std::size_t>(children) != needed) {
      fail(
          state.source, element,
          "needs exactly " + std::to_string(needed) + " children, got " + std::to_string(children));
    }
  }

  for (const XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::unique_ptr<TreeNode> child = buildNode(*c, depth + 1, state);
    if (auto* control = dynamic_cast<ControlNode*>(node.get())) {
      control->addChild(std::move(child));
    } else if (auto* decorator = dynamic_cast<DecoratorNode*>(node.get())) {
      decorator->setChild(std::move(child));
    } else {
      fail(state.source, element, "registered with children but built as a leaf");
    }
  }
  return node;
}

}  // namespace roomba_rrt::bt
