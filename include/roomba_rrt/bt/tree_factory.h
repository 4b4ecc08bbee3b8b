// Building behavior trees from a file, so users rearrange a behaviour without recompiling.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "roomba_rrt/bt/tree.h"

namespace tinyxml2 {
class XMLElement;
}

namespace roomba_rrt::bt {

/// A tree file that cannot be built. what() reads "FILE:LINE: <Element>: problem", naming the
/// element and its line, e.g. "roomba_tree.xml:7: <MoveForward>: a leaf cannot have children".
class TreeFileError : public std::runtime_error {
 public:
  TreeFileError(const std::string& source, int line, const std::string& message);
  int line() const { return line_; }

 private:
  int line_;
};

/// One element of the tree file, as a builder sees it.
struct NodeSpec {
  std::string type;                               ///< the element name, e.g. "Sequence"
  std::string name;                               ///< its `name` attribute, or `type`
  std::map<std::string, std::string> attributes;  ///< every other attribute
  /// The value of attribute `key` as an integer; std::invalid_argument naming it when it is
  /// missing or not an integer.
  long integer(const std::string& key) const;
};

/// Which children an element takes.
enum class NodeKind {
  kLeaf,       ///< no children
  kDecorator,  ///< exactly one child
  kControl,    ///< one or more children
};

/// Maps element names to node builders and builds trees from XML in the style of
/// BehaviorTree.CPP:
///
///     <root main_tree_to_execute="Roomba">
///       <BehaviorTree ID="Roomba">
///         <Selector>
///           <Sequence name="clean"> <MoveForward/> <MoveInSpiral/> </Sequence>
///           <Sequence name="recover"> <GoBack/> <Rotate/> </Sequence>
///         </Selector>
///       </BehaviorTree>
///     </root>
///
/// Built in: the control nodes Sequence, Selector (alias Fallback), ReactiveSequence,
/// ReactiveSelector (alias ReactiveFallback) and the decorators Inverter, Repeat (`num_cycles`),
/// Retry (`num_attempts`) and Timeout (`ticks`). Leaves are registered by the application.
///
/// Rejected with a TreeFileError naming the element and its line: malformed XML, an unknown
/// element, a leaf with children, a composite without children, a decorator without exactly one
/// child, an unknown or invalid attribute, a missing or ambiguous <BehaviorTree>.
class TreeFactory {
 public:
  using Builder = std::function<std::unique_ptr<TreeNode>(const NodeSpec&)>;

  /// A factory that knows the built-in control nodes and decorators.
  TreeFactory();

  /// Registers element `type`. `attributes` lists the attributes it accepts besides `name`.
  /// Registering a type twice throws std::invalid_argument.
  void registerNode(const std::string& type, NodeKind kind, Builder builder,
                    std::vector<std::string> attributes = {});
  /// Shorthand for a leaf without attributes.
  void registerLeaf(const std::string& type, Builder builder);

  Tree buildFromFile(const std::string& path) const;
  /// `source` names the text in error messages.
  Tree buildFromText(const std::string& xml, const std::string& source = "<string>") const;

  /// Registered element names, sorted.
  std::vector<std::string> types() const;

 private:
  struct Entry {
    NodeKind kind;
    Builder builder;
    std::vector<std::string> attributes;
  };
  /// Builds `element` and, recursively, its children.
  std::unique_ptr<TreeNode> buildNode(const tinyxml2::XMLElement& element,
                                      const std::string& source) const;

  std::map<std::string, Entry> entries_;
};

}  // namespace roomba_rrt::bt
