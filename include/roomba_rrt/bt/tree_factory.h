// Building behavior trees from a file, so users rearrange a behaviour without recompiling.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"
#include "roomba_rrt/bt/script.h"
#include "roomba_rrt/bt/tree.h"
#include "roomba_rrt/util/invalid_input.h"

namespace tinyxml2 {
class XMLElement;
}

namespace roomba_rrt::bt {

/// A tree file that cannot be built: the invalid input (util::InvalidInput) of a tree file, whose
/// field is the element and whose source is "FILE:LINE". what() reads "FILE:LINE: <Element>:
/// problem", e.g. "roomba_tree.xml:7: <MoveForward>: a leaf cannot have children", or
/// "FILE:LINE: problem" when no element is to blame (malformed XML, an unreadable file: line 0).
class TreeFileError : public util::InvalidInput {
 public:
  /// `element` is "<Name>", or "" for the file as a whole.
  TreeFileError(const std::string& source, int line, const std::string& element,
                const std::string& problem);
  int line() const { return line_; }

 private:
  int line_;
};

/// One element of the tree file, as a builder sees it.
///
/// For a node type registered with ports, the factory has already checked every attribute
/// before the builder runs (required ports present, literals of the right type and range, keys
/// of the right type), so input(), output() and literal() only fail when the builder asks for a
/// port under another type than it declared (a programming error: std::invalid_argument).
struct NodeSpec {
  std::string type;  ///< the element name, e.g. "Sequence"
  std::string name;  ///< its `name` attribute, or `type`
  /// Every other attribute, and the defaults of the ports the file leaves out.
  std::map<std::string, std::string> attributes;
  Blackboard* blackboard = nullptr;  ///< the tree's blackboard
  const PortList* ports = nullptr;   ///< the node type's ports (empty for plain attributes)
  double tick_rate = 60.0;           ///< the factory's tick rate (Hz)
  /// A script variable's blackboard key, through the SubTree's remapping as a port's `{key}`.
  Script::KeyOf key_of;

  /// The literal value of port `port` (attribute or default).
  template <class T>
  T literal(const std::string& port) const {
    T value{};
    const std::string error = LiteralParser<T>::parse(text(port), value);
    if (!error.empty()) throw std::invalid_argument("port '" + port + "' " + error);
    return value;
  }
  /// Input port `port`: its literal, or its blackboard entry.
  template <class T>
  InputPort<T> input(const std::string& port) const {
    std::string key;
    if (parseBlackboardKey(text(port), key)) return InputPort<T>::key(board().declare<T>(key));
    return InputPort<T>::literal(literal<T>(port));
  }
  /// The script in attribute `port` (std::invalid_argument on a syntax error).
  Script script(const std::string& port) const { return Script(text(port), key_of); }
  /// The blackboard key attribute `port` names, as `{key}` or as a bare name (SetBlackboard's
  /// `output_key`).
  std::string keyName(const std::string& port) const {
    std::string key;
    return parseBlackboardKey(text(port), key) ? key : key_of(text(port));
  }
  /// Output port `port`: its blackboard entry.
  template <class T>
  OutputPort<T> output(const std::string& port) const {
    std::string key;
    if (!parseBlackboardKey(text(port), key)) {
      throw std::invalid_argument("output port '" + port + "' needs a blackboard key like {" +
                                  port + "}");
    }
    return OutputPort<T>(board().declare<T>(key));
  }

 private:
  const std::string& text(const std::string& port) const;
  Blackboard& board() const;
};

/// Which children an element takes, and how BehaviorTree.CPP's tools draw it.
enum class NodeKind {
  kLeaf,       ///< an action: no children
  kCondition,  ///< a condition (a ConditionNode): no children
  kDecorator,  ///< exactly one child
  kControl,    ///< one or more children
};

/// Maps element names to node builders (the registry, src/bt/tree_factory.cpp) and builds trees
/// from XML in BehaviorTree.CPP v4's format (the reader, src/bt/xml_parsing.cpp; doc/behaviours.md,
/// "Tree files"):
///
///     <root BTCPP_format="4" main_tree_to_execute="Roomba">
///       <include path="other_trees.xml"/>
///       <BehaviorTree ID="Roomba">
///         <Fallback>
///           <Sequence name="clean"> <MoveForward/> <MoveInSpiral/> </Sequence>
///           <SubTree ID="Recover" _autoremap="true"/>
///         </Fallback>
///       </BehaviorTree>
///       <BehaviorTree ID="Recover"> <Sequence> <GoBack/> <Rotate/> </Sequence> </BehaviorTree>
///     </root>
///
/// Built in, with BehaviorTree.CPP v4's names and ports: the control nodes Sequence,
/// SequenceWithMemory, Fallback, ReactiveSequence, ReactiveFallback, and Nav2's
/// PipelineSequence and RecoveryNode (`number_of_retries`, two children); the decorators
/// Inverter, Repeat (`num_cycles`), RetryUntilSuccessful (`num_attempts`), Timeout (`msec`, or
/// our deterministic `ticks`) and Nav2's RateController (`hz`); BehaviorTree.CPP 4's other
/// standard nodes (registerStandardNodes(), doc/behaviours.md) and the pre/post-condition
/// attributes `_failureIf`, `_successIf`, `_skipIf`, `_while`, `_onSuccess`, `_onFailure`,
/// `_post`, `_onHalted` on any node, a SubTree's guarding its tree's root (node_conditions.h);
/// SubTree (`ID`, port
/// remapping `port="{parent_key}"` or `port="literal"`, `_autoremap`); BehaviorTree.CPP's explicit
/// form
/// `<Action ID="MoveForward"/>` (also Condition, Control, Decorator; Groot 1 writes it), read as
/// `<MoveForward/>`; `<include path="...">` (relative to
/// the including file) under <root>; a <TreeNodesModel> under <root> (Groot2 writes one) is
/// ignored. Leaves are registered by the application. The spellings of BehaviorTree.CPP v3 and of
/// our earlier files (Selector, ReactiveSelector, Retry, RetryUntilSuccesful, SequenceStar) are
/// read as their v4 names, with a notice naming the v4 spelling (setNoticeHandler()).
///
/// Rejected with a TreeFileError naming the element and its line: malformed XML, an unknown
/// element, a leaf with children, a composite without children, a decorator without exactly one
/// child, an unknown or invalid attribute, a missing or ambiguous <BehaviorTree>, two
/// <BehaviorTree> elements with the same ID (also across included files), a SubTree naming no
/// tree or itself, an include that cannot be read or includes itself, a BTCPP_format other than
/// 3 or 4, nesting deeper than kMaxDepth, more than kMaxNodes nodes; and for ports: a missing
/// required port, a literal of the wrong type or out of its range (e.g.
/// num_cycles="4294967295"), a literal where an output needs a key, a key used with two types
/// (by two ports, or by a port and the application), and a key that an input reads but that no
/// output port of the tree writes and the application did not declare.
///
/// A SubTree's keys are its own, as in BehaviorTree.CPP: `{key}` inside it is the parent's
/// `{key}` only when the SubTree element remaps it (`key="{parent_key}"`, or a literal value) or
/// says `_autoremap="true"`; otherwise it is private to that SubTree instance (on the shared
/// blackboard as "ID#n/key").
class TreeFactory {
 public:
  using Builder = std::function<std::unique_ptr<TreeNode>(const NodeSpec&)>;

  /// Deepest nesting of nodes below <BehaviorTree> (the root node is at depth 1).
  static constexpr int kMaxDepth = 64;
  /// Most nodes in one tree.
  static constexpr int kMaxNodes = 10000;

  /// A factory that knows the built-in control nodes and decorators.
  TreeFactory();

  /// Registers element `type`. `attributes` lists the attributes it accepts besides `name`
  /// (passed to the builder as text). Registering a type twice throws std::invalid_argument.
  void registerNode(const std::string& type, NodeKind kind, Builder builder,
                    std::vector<std::string> attributes = {});
  /// Registers element `type` with the ports `ports` (see NodeSpec and ports.h).
  void registerNodeWithPorts(const std::string& type, NodeKind kind, Builder builder,
                             PortList ports);
  /// Registers node class `Node` as element `type`: its kind from its base class (ControlNode,
  /// DecoratorNode, ConditionNode, else an action leaf), its ports from `Node::providedPorts()`.
  template <class Node>
  void registerNodeType(const std::string& type, Builder builder) {
    constexpr NodeKind kind = std::is_base_of_v<ControlNode, Node>     ? NodeKind::kControl
                              : std::is_base_of_v<DecoratorNode, Node> ? NodeKind::kDecorator
                              : std::is_base_of_v<ConditionNode, Node> ? NodeKind::kCondition
                                                                       : NodeKind::kLeaf;
    registerNodeWithPorts(type, kind, std::move(builder), Node::providedPorts());
  }
  /// Shorthand for a leaf without attributes.
  void registerLeaf(const std::string& type, Builder builder);

  /// Where notices about a tree file go (a v3 spelling, a missing BTCPP_format): one line each,
  /// "FILE:LINE: ...". By default they are written to std::cerr; an empty handler drops them.
  using NoticeHandler = std::function<void(const std::string&)>;
  void setNoticeHandler(NoticeHandler handler) { notice_ = std::move(handler); }

  /// Tick rate of the trees built (Hz, default 60): RateController turns its `hz` into ticks
  /// with it. Must be finite and > 0 (util::InvalidInput).
  void setTickRate(double hz);

  /// Builds a tree with a fresh blackboard.
  Tree buildFromFile(const std::string& path) const;
  /// `source` names the text in error messages.
  Tree buildFromText(const std::string& xml, const std::string& source = "<string>") const;
  /// Builds a tree on `blackboard`, whose keys the application declared (and may have written)
  /// beforehand; the tree keeps it.
  Tree buildFromFile(const std::string& path, std::shared_ptr<Blackboard> blackboard) const;
  Tree buildFromText(const std::string& xml, const std::string& source,
                     std::shared_ptr<Blackboard> blackboard) const;

  /// The ports of element `type` (std::invalid_argument when it is unknown).
  const PortList& ports(const std::string& type) const;
  /// Every registered element name, sorted (built-ins and the application's).
  std::vector<std::string> registeredTypes() const;
  /// The registered types that the tree file at `path` (and what it includes) uses anywhere, under
  /// their v4 names; elements that are no registered type are left out. TreeFileError when the
  /// file or an include cannot be read or parsed.
  std::set<std::string> typesUsedIn(const std::string& path) const;

  /// The <TreeNodesModel> of every registered type that BehaviorTree.CPP does not build in, with
  /// its ports (name, type, default, description), as a BTCPP_format="4" document: Groot2 opens
  /// our trees with it and edits their ports.
  std::string treeNodesModel() const;

 private:
  struct Entry {
    NodeKind kind;
    Builder builder;
    PortList ports;
  };
  struct Library;
  struct Scope;
  struct BuildState;

  /// Parses `xml` (from `source`) into `library`: its <BehaviorTree> definitions and, recursively,
  /// those of the files it includes. Returns the document's <root>.
  const tinyxml2::XMLElement& load(const std::string& xml, const std::string& source,
                                   Library& library) const;
  /// The registered entry for element `element` (a v3 spelling: its v4 entry, with a notice).
  const Entry& entryFor(const tinyxml2::XMLElement& element, const BuildState& state) const;
  /// Builds `element` at `depth` and, recursively, its children.
  std::unique_ptr<TreeNode> buildNode(const tinyxml2::XMLElement& element, int depth,
                                      BuildState& state) const;
  /// Builds a <SubTree> element: the tree it names, in a scope of its own.
  std::unique_ptr<TreeNode> buildSubTree(const tinyxml2::XMLElement& element, int depth,
                                         BuildState& state) const;
  /// The NodeSpec of `element`: its name and attributes, keys resolved through the scope.
  NodeSpec readAttributes(const tinyxml2::XMLElement& element, const Entry& entry,
                          BuildState& state) const;
  /// Checks every port of `spec` (required, literal type and range, key types) and declares
  /// the keys; fills in defaults.
  void bindPorts(const tinyxml2::XMLElement& element, const Entry& entry, NodeSpec& spec,
                 BuildState& state) const;
  /// The pre/post-condition scripts in `element`'s attributes (`_successIf`, ...), or nullptr.
  std::shared_ptr<const NodeConditions> readConditions(const tinyxml2::XMLElement& element,
                                                       const Script::KeyOf& key_of,
                                                       BuildState& state) const;
  void notice(const std::string& text) const;
  /// Registers the standard nodes of BehaviorTree.CPP 4 besides the ones the tree files of this
  /// package were first written with (doc/behaviours.md lists them all).
  void registerStandardNodes();

  std::map<std::string, Entry> entries_;
  double tick_rate_ = 60.0;
  NoticeHandler notice_;
};

}  // namespace roomba_rrt::bt
