// The part of BehaviorTree.CPP's script language that its Script nodes and pre/post-conditions
// (`_successIf="battery < 10"`, `_onSuccess="done := true"`) need, on our typed blackboard.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "roomba_rrt/bt/blackboard.h"

namespace roomba_rrt::bt {

/// A value in a script: a number (double, as BT.CPP's scripts compute), a string or a boolean.
using ScriptValue = std::variant<double, std::string, bool>;

/// A script that cannot be evaluated on the blackboard as it is (a key never written, a string
/// added to a number, an int key given 0.5): what() says which.
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A parsed script: statements separated by ';', its value that of the last one. Scripts are
/// BT.CPP's Script and ScriptCondition nodes, Precondition's `if`, and the pre/post-conditions
/// (node_conditions.h).
///
/// The subset of BT.CPP's language (doc/behaviours.md, "Scripts"):
/// - literals: numbers (`3`, `-0.5`, `1e3`), strings in single quotes (`'docked'`), `true`,
///   `false`;
/// - variables: blackboard keys by name (`battery`, letters, digits and `_`, through the SubTree's
///   remapping like a port's `{battery}`); keys holding bool, int, long, double or string;
/// - assignment: `key := expr` (creates the key, as a double, string or bool, if it is new),
///   `key = expr` (the key must exist); an int key takes only whole numbers in its range;
/// - arithmetic `+ - * /` and unary `-` on numbers; comparisons `== != < <= > >=` on two
///   numbers, two strings, or two booleans (== and != only); `&&`, `||`, `!` on booleans (a
///   number is true when it is not 0); parentheses.
/// Not supported: BT.CPP's `..` (string concatenation), `? :`, `+=` and friends, bit operators
/// and enums. At most 64 levels of nesting and 1000 operands and operators (the parser and the
/// evaluation recurse).
class Script {
 public:
  /// Maps a variable name to its blackboard key (the SubTree's scope); std::invalid_argument
  /// when the name cannot be a key.
  using KeyOf = std::function<std::string(const std::string& name)>;

  /// Parses `code`; std::invalid_argument saying what and where ("at column 7") on a syntax
  /// error or an empty script.
  Script(const std::string& code, const KeyOf& key_of);
  ~Script();
  Script(Script&&) noexcept;
  Script& operator=(Script&&) noexcept;

  /// Runs the script on `board`: its assignments write keys, and the value of the last
  /// statement is returned. ScriptError when it cannot be evaluated.
  ScriptValue evaluate(Blackboard& board) const;
  /// evaluate() as a condition: a boolean, or a number that is not 0 (ScriptError otherwise).
  bool isTrue(Blackboard& board) const;

  const std::string& code() const { return code_; }

  struct Expr;

 private:
  std::string code_;
  std::vector<std::unique_ptr<Expr>> statements_;
};

/// "3", "0.5", "'text'", "true" (for messages).
std::string show(const ScriptValue& value);

/// The value of blackboard key `key` (`name` in messages) as a script sees it; ScriptError when
/// it was never written or holds a type scripts do not know.
ScriptValue readEntry(const Blackboard& board, const std::string& key, const std::string& name);
/// Writes `value` to `key` as an assignment does: `create` (`:=`) declares a missing key with
/// the value's type; an existing key keeps its type (ScriptError when `value` does not fit).
void writeEntry(Blackboard& board, const std::string& key, const std::string& name,
                const ScriptValue& value, bool create);

}  // namespace roomba_rrt::bt
