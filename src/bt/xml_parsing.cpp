// The XML reader of TreeFactory (BehaviorTree.CPP's xml_parsing): tree files in, trees out
// (load, includes, SubTree scopes, attributes bound to ports), and the TreeNodesModel written
// for Groot2. The node registry is tree_factory.cpp.
#include <tinyxml2.h>

#include <algorithm>
#include <iostream>
#include <set>
#include <sstream>

#include "roomba_rrt/bt/node_conditions.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "roomba_rrt/util/text_file.h"

namespace roomba_rrt::bt {
namespace {

using tinyxml2::XMLElement;

int childElementCount(const XMLElement& element) {
  int count = 0;
  for (const XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement()) ++count;
  return count;
}

[[noreturn]] void fail(const std::string& source, const XMLElement& element,
                       const std::string& message) {
  throw TreeFileError(source, element.GetLineNum(), "<" + std::string(element.Name()) + ">",
                      message);
}

/// BehaviorTree.CPP's explicit form, `<Action ID="MoveForward"/>` for `<MoveForward/>` (Groot 1
/// writes it, v4 reads it): the element names the category, its ID the node type.
bool isExplicitForm(const XMLElement& element) {
  static const std::set<std::string> kCategories = {"Action", "Condition", "Control", "Decorator"};
  return kCategories.count(element.Name()) > 0;
}

/// The node type `element` names: its ID in the explicit form ("" if it has none), else its name.
std::string typeOf(const XMLElement& element) {
  if (!isExplicitForm(element)) return element.Name();
  const char* id = element.Attribute("ID");
  return id ? id : "";
}

/// The spellings of BehaviorTree.CPP v3 and of our earlier tree files, and their v4 names.
const std::map<std::string, std::string>& legacySpellings() {
  static const std::map<std::string, std::string> kSpellings = {
      {"Selector", "Fallback"},
      {"ReactiveSelector", "ReactiveFallback"},
      {"Retry", "RetryUntilSuccessful"},
      {"RetryUntilSuccesful", "RetryUntilSuccessful"},  // v3's misspelling
      {"SequenceStar", "SequenceWithMemory"},
  };
  return kSpellings;
}

/// The nodes BehaviorTree.CPP v4 builds in: Groot2 knows them without a model.
bool builtIntoBehaviorTreeCpp(const std::string& type) {
  static const std::set<std::string> kBuiltIn = {"AlwaysFailure",
                                                 "AsyncFallback",
                                                 "AsyncSequence",
                                                 "AlwaysSuccess",
                                                 "Delay",
                                                 "Fallback",
                                                 "ForceFailure",
                                                 "ForceSuccess",
                                                 "IfThenElse",
                                                 "Inverter",
                                                 "KeepRunningUntilFailure",
                                                 "Parallel",
                                                 "ParallelAll",
                                                 "Precondition",
                                                 "RunOnce",
                                                 "ReactiveFallback",
                                                 "ReactiveSequence",
                                                 "Repeat",
                                                 "RetryUntilSuccessful",
                                                 "Script",
                                                 "ScriptCondition",
                                                 "Sequence",
                                                 "SequenceWithMemory",
                                                 "SetBlackboard",
                                                 "SkipUnlessUpdated",
                                                 "WaitValueUpdate",
                                                 "WasEntryUpdated",
                                                 "Sleep",
                                                 "SubTree",
                                                 "Switch2",
                                                 "Switch3",
                                                 "Switch4",
                                                 "Switch5",
                                                 "Switch6",
                                                 "Timeout",
                                                 "TryCatch",
                                                 "UnsetBlackboard",
                                                 "WhileDoElse"};
  return kBuiltIn.count(type) > 0;
}

/// The directory part of `path` with its '/', or "" (relative includes of a text: the cwd).
std::string directoryOf(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

/// A tree file's text: a readable regular file of at most 1 MiB (not a directory or a device an
/// include might name), else a TreeFileError saying why.
std::string readFile(const std::string& path) {
  constexpr std::size_t kMaxTreeFileBytes = 1 << 20;
  try {
    return util::readTextFile(path, kMaxTreeFileBytes, "tree file");
  } catch (const util::InvalidInput& error) {
    throw TreeFileError(path, 0, "", error.problem());
  }
}

/// "port 'goal' (Pose2D: the goal pose)" for messages.
std::string describe(const PortInfo& port) {
  return "port '" + port.name + "' (" + port.type_name +
         (port.description.empty() ? "" : ": " + port.description) + ")";
}

}  // namespace

/// Every <BehaviorTree> a build can reach: the main file's and its includes', by ID. The
/// documents stay alive as long as the library, since the definitions point into them.
struct TreeFactory::Library {
  struct Definition {
    const XMLElement* element;
    std::string source;  ///< the file (or text) that defines it, for messages
  };
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> documents;
  std::map<std::string, Definition> trees;
  std::vector<std::string> loading;  ///< the include chain being read (cycle check)
};

/// Where the blackboard keys of the nodes being built live: the main tree's are the
/// blackboard's own; a SubTree's are remapped to its parent's or private to it.
struct TreeFactory::Scope {
  const Scope* parent = nullptr;             ///< nullptr: the main tree
  std::map<std::string, std::string> remap;  ///< subtree key -> text in the parent's scope
  bool autoremap = false;
  std::string prefix;  ///< of private keys, "ID#n/"

  /// An attribute's text as the blackboard sees it: `{key}` resolved to the main tree's key (or
  /// to the literal a SubTree passed for it); any other text unchanged.
  std::string resolve(const std::string& text) const {
    std::string key;
    if (!parent || !parseBlackboardKey(text, key)) return text;
    const auto it = remap.find(key);
    if (it != remap.end()) return parent->resolve(it->second);
    if (autoremap) return parent->resolve(text);
    return "{" + prefix + key + "}";
  }
  /// The blackboard key a script's variable `name` is in this scope (a port's `{name}`).
  std::string keyOf(const std::string& name) const {
    std::string key;
    if (!parseBlackboardKey(resolve("{" + name + "}"), key)) {
      throw std::invalid_argument("the SubTree passes a literal for it, not a key");
    }
    return key;
  }
};

/// What the build of one tree collects to check the blackboard keys at the end.
struct TreeFactory::BuildState {
  std::string source;  ///< the file of the definition being built
  const Library* library = nullptr;
  const Scope* scope = nullptr;
  std::vector<std::string> subtrees;     ///< the SubTree IDs being built (cycle check)
  std::map<std::string, int> instances;  ///< SubTree ID -> instances built so far
  Blackboard* blackboard = nullptr;
  std::set<std::string> declared_before;  ///< keys the application declared
  std::set<std::string> named;            ///< keys the tree file names
  std::set<std::string> written;          ///< keys some output port writes
  struct Read {
    std::string key;
    std::string port;
    std::string source;
    const XMLElement* element;
  };
  std::vector<Read> reads;  ///< input ports bound to keys
  int nodes = 0;
};

TreeFileError::TreeFileError(const std::string& source, int line, const std::string& element,
                             const std::string& problem)
    : util::InvalidInput(element, problem, source + ":" + std::to_string(line)), line_(line) {}

Tree TreeFactory::buildFromFile(const std::string& path) const {
  return buildFromFile(path, std::make_shared<Blackboard>());
}

Tree TreeFactory::buildFromText(const std::string& xml, const std::string& source) const {
  return buildFromText(xml, source, std::make_shared<Blackboard>());
}

Tree TreeFactory::buildFromFile(const std::string& path,
                                std::shared_ptr<Blackboard> blackboard) const {
  return buildFromText(readFile(path), path, std::move(blackboard));
}

const XMLElement& TreeFactory::load(const std::string& xml, const std::string& source,
                                    Library& library) const {
  auto& loading = library.loading;
  if (std::find(loading.begin(), loading.end(), source) != loading.end()) {
    std::string chain;
    for (const std::string& file : loading) chain += file + " -> ";
    throw TreeFileError(source, 0, "", "the file includes itself (" + chain + source + ")");
  }
  library.documents.push_back(std::make_unique<tinyxml2::XMLDocument>());
  tinyxml2::XMLDocument& document = *library.documents.back();
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw TreeFileError(source, document.ErrorLineNum(), "",
                        std::string("malformed XML: ") + document.ErrorStr());
  }
  const XMLElement* root = document.RootElement();
  if (!root || std::string(root->Name()) != "root") {
    throw TreeFileError(source, root ? root->GetLineNum() : 0, "",
                        "the document element must be <root>");
  }
  const char* format = root->Attribute("BTCPP_format");
  if (format && std::string(format) != "4" && std::string(format) != "3") {
    fail(source, *root, std::string("BTCPP_format \"") + format + "\" is not supported (4 or 3)");
  }

  loading.push_back(source);
  for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "BehaviorTree") {
      // A tree without an ID can only be the main file's single tree: SubTree cannot name it.
      const char* id = e->Attribute("ID");
      if (!id) continue;
      const auto [it, fresh] = library.trees.emplace(id, Library::Definition{e, source});
      if (!fresh) {
        fail(source, *e,
             std::string("ID \"") + id + "\" is used twice (first on " +
                 (it->second.source == source ? "line " : it->second.source + ":") +
                 std::to_string(it->second.element->GetLineNum()) + ")");
      }
    } else if (name == "include") {
      if (e->Attribute("ros_pkg")) {
        fail(source, *e, "ros_pkg is not supported: give the file in path, relative to this file");
      }
      const char* path = e->Attribute("path");
      if (!path || !*path) fail(source, *e, "needs a path attribute");
      const std::string file = path[0] == '/' ? path : directoryOf(source) + path;
      std::string text;
      try {
        text = readFile(file);
      } catch (const TreeFileError& error) {
        fail(source, *e, std::string("cannot include \"") + path + "\": " + error.what());
      }
      load(text, file, library);
    } else if (name != "TreeNodesModel") {  // Groot2 keeps its model in the file: not ours to read
      fail(source, *e, "unknown element under <root> (BehaviorTree, include or TreeNodesModel)");
    }
  }
  loading.pop_back();
  return *root;
}

Tree TreeFactory::buildFromText(const std::string& xml, const std::string& source,
                                std::shared_ptr<Blackboard> blackboard) const {
  if (!blackboard) throw std::invalid_argument("buildFromText: the blackboard is null");
  Library library;
  const XMLElement& root = load(xml, source, library);

  // Pick the <BehaviorTree> to build: the one named by main_tree_to_execute, or the main file's
  // only one.
  const XMLElement* chosen = nullptr;
  if (const char* main_id = root.Attribute("main_tree_to_execute")) {
    const auto it = library.trees.find(main_id);
    if (it == library.trees.end()) {
      fail(source, root, std::string("no <BehaviorTree ID=\"") + main_id + "\">");
    }
    chosen = it->second.element;
  } else {
    int trees = 0;
    for (const XMLElement* t = root.FirstChildElement("BehaviorTree"); t;
         t = t->NextSiblingElement("BehaviorTree")) {
      chosen = chosen ? chosen : t;
      ++trees;
    }
    if (trees == 0) fail(source, root, "no <BehaviorTree> element");
    if (trees > 1) {
      fail(source, root, "several <BehaviorTree> elements; name one in main_tree_to_execute");
    }
  }

  const Scope main_scope;
  BuildState state;
  state.library = &library;
  state.scope = &main_scope;
  state.blackboard = blackboard.get();
  state.source = source;
  for (const auto& [id, definition] : library.trees) {
    if (definition.element == chosen) {
      state.source = definition.source;
      state.subtrees.push_back(id);
    }
  }
  if (childElementCount(*chosen) != 1) {
    fail(state.source, *chosen,
         "needs exactly one root node, got " + std::to_string(childElementCount(*chosen)));
  }
  std::unique_ptr<TreeNode> node = buildNode(*chosen->FirstChildElement(), 1, state);
  // Keys the application declared count as written by it (it may write them between ticks).
  for (const auto& read : state.reads) {
    if (state.written.count(read.key) == 0 && state.declared_before.count(read.key) == 0) {
      fail(read.source, *read.element,
           "port '" + read.port + "' reads blackboard key '" + read.key +
               "', which nothing writes (no output port of the tree names it and the "
               "application did not declare it)");
    }
  }
  return Tree(std::move(node), std::move(blackboard));
}

const TreeFactory::Entry& TreeFactory::entryFor(const XMLElement& element,
                                                const BuildState& state) const {
  std::string type = typeOf(element);
  if (type.empty()) fail(state.source, element, "needs an ID attribute naming the node type");
  const auto legacy = legacySpellings().find(type);
  if (legacy != legacySpellings().end()) {
    notice(state.source + ":" + std::to_string(element.GetLineNum()) + ": <" + type +
           "> is read as <" + legacy->second + ">, its BehaviorTree.CPP v4 name: write that");
    type = legacy->second;
  }
  const auto entry = entries_.find(type);
  if (entry == entries_.end()) {
    fail(state.source, element,
         isExplicitForm(element) ? "unknown node type '" + type + "'" : "unknown node type");
  }
  return entry->second;
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
  if (std::string(element.Name()) == "SubTree") return buildSubTree(element, depth, state);
  const Entry& e = entryFor(element, state);
  NodeSpec spec = readAttributes(element, e, state);
  bindPorts(element, e, spec, state);

  const int children = childElementCount(element);
  if ((e.kind == NodeKind::kLeaf || e.kind == NodeKind::kCondition) && children > 0) {
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
  node->setConditions(readConditions(element, spec.key_of, state));
  const auto legacy = legacySpellings().find(spec.type);
  node->setTypeName(legacy == legacySpellings().end() ? spec.type : legacy->second);
  auto* control = dynamic_cast<ControlNode*>(node.get());
  auto* decorator = dynamic_cast<DecoratorNode*>(node.get());
  if (control) {
    const std::string problem = control->childCountProblem(static_cast<std::size_t>(children));
    if (!problem.empty()) fail(state.source, element, problem);
  }
  if (children > 0 && !control && !decorator) {
    fail(state.source, element, "registered with children but built as a leaf");
  }
  for (const XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::unique_ptr<TreeNode> child = buildNode(*c, depth + 1, state);
    if (control) {
      control->addChild(std::move(child));
    } else {
      decorator->setChild(std::move(child));
    }
  }
  return node;
}

std::unique_ptr<TreeNode> TreeFactory::buildSubTree(const XMLElement& element, int depth,
                                                    BuildState& state) const {
  if (childElementCount(element) > 0) fail(state.source, element, "a SubTree cannot have children");
  const char* id = element.Attribute("ID");
  if (!id || !*id) fail(state.source, element, "needs an ID attribute naming a <BehaviorTree>");
  const auto definition = state.library->trees.find(id);
  if (definition == state.library->trees.end()) {
    fail(state.source, element, std::string("no <BehaviorTree ID=\"") + id + "\">");
  }
  if (std::find(state.subtrees.begin(), state.subtrees.end(), id) != state.subtrees.end()) {
    std::string chain;
    for (const std::string& tree : state.subtrees) chain += tree + " -> ";
    fail(state.source, element, std::string("the tree contains itself (") + chain + id + ")");
  }

  Scope scope;
  scope.parent = state.scope;
  scope.prefix = std::string(id) + "#" + std::to_string(++state.instances[id]) + "/";
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    const std::string value = a->Value();
    if (key == "ID" || key == "name") continue;
    if (NodeConditions::isConditionAttribute(key)) continue;  // on the tree's root, below
    if (key == "_autoremap") {
      if (value != "true" && value != "false") {
        fail(state.source, element,
             "attribute '_autoremap' must be true or false, got '" + value + "'");
      }
      scope.autoremap = value == "true";
    } else if (!key.empty() && key.front() == '_') {
      fail(state.source, element, "unknown attribute '" + key + "'");
    } else {
      scope.remap[key] = value == "{=}" ? "{" + key + "}" : value;  // {=}: the same name
    }
  }

  const XMLElement& tree = *definition->second.element;
  const std::string caller_source = state.source;
  state.source = definition->second.source;
  if (childElementCount(tree) != 1) {
    fail(state.source, tree,
         "needs exactly one root node, got " + std::to_string(childElementCount(tree)));
  }
  const Scope* caller_scope = state.scope;
  state.scope = &scope;
  state.subtrees.push_back(id);
  std::unique_ptr<TreeNode> node = buildNode(*tree.FirstChildElement(), depth + 1, state);
  state.subtrees.pop_back();
  state.scope = caller_scope;
  state.source = caller_source;
  // Pre/post-conditions on the SubTree element guard the tree's root, in the caller's scope.
  if (auto conditions = readConditions(
          element, [caller_scope](const std::string& name) { return caller_scope->keyOf(name); },
          state)) {
    if (node->hasConditions()) {
      fail(state.source, element,
           std::string("both this SubTree and the root of tree \"") + id +
               "\" have pre/post-conditions: keep them in one place");
    }
    node->setConditions(std::move(conditions));
  }
  return node;
}

NodeSpec TreeFactory::readAttributes(const XMLElement& element, const Entry& entry,
                                     BuildState& state) const {
  NodeSpec spec;
  spec.type = typeOf(element);
  spec.name = spec.type;
  const bool explicit_form = isExplicitForm(element);
  spec.blackboard = state.blackboard;
  spec.ports = &entry.ports;
  spec.tick_rate = tick_rate_;
  spec.key_of = [scope = state.scope](const std::string& name) { return scope->keyOf(name); };
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    if (key == "name") {
      spec.name = a->Value();
      continue;
    }
    if (explicit_form && key == "ID") continue;               // the type, read by typeOf()
    if (NodeConditions::isConditionAttribute(key)) continue;  // read by buildNode()
    const bool known = std::any_of(entry.ports.begin(), entry.ports.end(),
                                   [&](const PortInfo& p) { return p.name == key; });
    if (!known) fail(state.source, element, "unknown attribute '" + key + "'");
    spec.attributes[key] = state.scope->resolve(a->Value());
  }
  return spec;
}

std::shared_ptr<const NodeConditions> TreeFactory::readConditions(const XMLElement& element,
                                                                  const Script::KeyOf& key_of,
                                                                  BuildState& state) const {
  std::shared_ptr<NodeConditions> conditions;
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    if (!NodeConditions::isConditionAttribute(a->Name())) continue;
    if (!conditions) {
      conditions = std::make_shared<NodeConditions>();
      conditions->board = state.blackboard;
    }
    try {
      conditions->set(a->Name(), Script(a->Value(), key_of));
    } catch (const std::invalid_argument& error) {
      fail(state.source, element, std::string("attribute '") + a->Name() + "': " + error.what());
    }
  }
  return conditions;
}

void TreeFactory::bindPorts(const XMLElement& element, const Entry& entry, NodeSpec& spec,
                            BuildState& state) const {
  for (const PortInfo& port : entry.ports) {
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
      if (port.direction != PortDirection::kInput) {
        state.written.insert(key);
      } else {
        state.reads.push_back({key, port.name, state.source, &element});
      }
    } else if (port.direction != PortDirection::kInput) {
      fail(state.source, element,
           std::string(port.direction == PortDirection::kOutput ? "output " : "inout ") +
               describe(port) + " needs a blackboard key like {" + port.name + "}, got '" +
               it->second + "'");
    } else {
      const std::string problem = port.check(port, it->second);
      if (!problem.empty()) {
        fail(state.source, element, "attribute '" + port.name + "' " + problem);
      }
    }
  }
}

std::set<std::string> TreeFactory::typesUsedIn(const std::string& path) const {
  Library library;
  load(readFile(path), path, library);
  std::set<std::string> used;
  std::vector<const XMLElement*> stack;
  for (const auto& tree : library.trees) stack.push_back(tree.second.element);
  while (!stack.empty()) {
    const XMLElement* element = stack.back();
    stack.pop_back();
    for (const XMLElement* c = element->FirstChildElement(); c; c = c->NextSiblingElement()) {
      std::string type = typeOf(*c);
      const auto legacy = legacySpellings().find(type);
      if (legacy != legacySpellings().end()) type = legacy->second;
      if (entries_.count(type)) used.insert(type);
      stack.push_back(c);
    }
  }
  return used;
}

std::string TreeFactory::treeNodesModel() const {
  static const std::map<NodeKind, const char*> kCategory = {{NodeKind::kLeaf, "Action"},
                                                            {NodeKind::kCondition, "Condition"},
                                                            {NodeKind::kDecorator, "Decorator"},
                                                            {NodeKind::kControl, "Control"}};
  tinyxml2::XMLPrinter out;
  out.PushHeader(false, true);
  out.OpenElement("root");
  out.PushAttribute("BTCPP_format", "4");
  out.OpenElement("TreeNodesModel");
  for (const auto& [type, entry] : entries_) {
    if (builtIntoBehaviorTreeCpp(type)) continue;
    out.OpenElement(kCategory.at(entry.kind));
    out.PushAttribute("ID", type.c_str());
    for (const PortInfo& port : entry.ports) {
      out.OpenElement(port.direction == PortDirection::kInput    ? "input_port"
                      : port.direction == PortDirection::kOutput ? "output_port"
                                                                 : "inout_port");
      out.PushAttribute("name", port.name.c_str());
      out.PushAttribute("type", port.type_name.c_str());
      if (port.default_value) out.PushAttribute("default", port.default_value->c_str());
      if (!port.description.empty()) out.PushText(port.description.c_str());
      out.CloseElement();
    }
    out.CloseElement();
  }
  out.CloseElement();
  out.CloseElement();
  return out.CStr();
}

}  // namespace roomba_rrt::bt
