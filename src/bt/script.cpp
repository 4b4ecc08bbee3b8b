#include "roomba_rrt/bt/script.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace roomba_rrt::bt {

/// One node of a statement's syntax tree.
struct Script::Expr {
  enum class Op {
    kLiteral,
    kVariable,
    kAssign,
    kCreate,  // leaves and assignments (`=`, `:=`)
    kNot,
    kNegate,  // unary
    kAdd,
    kSubtract,
    kMultiply,
    kDivide,  // arithmetic
    kEqual,
    kNotEqual,
    kLess,
    kLessEqual,
    kGreater,
    kGreaterEqual,
    kAnd,
    kOr,
  };
  Op op = Op::kLiteral;
  ScriptValue literal;
  std::string key;   ///< the blackboard key of a variable or an assignment's target
  std::string name;  ///< the variable as the script names it (for messages)
  std::unique_ptr<Expr> left, right;
};

namespace {

using Expr = Script::Expr;
using Op = Expr::Op;

std::string kindOf(const ScriptValue& v) {
  return std::holds_alternative<double>(v) ? "a number"
         : std::holds_alternative<bool>(v) ? "a boolean"
                                           : "a string";
}

/// Recursive descent over the code, lowest precedence first:
/// statement := name (':=' | '=') statement | or;  or := and ('||' and)*;
/// and := comparison ('&&' comparison)*;  comparison := sum (('=='|'!='|'<'|...) sum)?;
/// sum := product (('+'|'-') product)*;  product := unary (('*'|'/') unary)*;
/// unary := ('!'|'-') unary | number | 'string' | true | false | name | '(' or ')'.
class Parser {
 public:
  Parser(const std::string& code, const Script::KeyOf& key_of) : code_(code), key_of_(key_of) {}

  std::vector<std::unique_ptr<Expr>> statements() {
    std::vector<std::unique_ptr<Expr>> out;
    while (true) {
      skipSpace();
      if (at_ == code_.size()) break;
      if (accept(";")) continue;
      out.push_back(statement());
      skipSpace();
      if (at_ < code_.size() && !accept(";")) fail("expected ';' or the end");
    }
    if (out.empty()) throw std::invalid_argument("the script is empty");
    return out;
  }

 private:
  /// Parsing and evaluating recurse: a script nests at most kMaxDepth levels (parentheses,
  /// `!`, `-`, chained assignments) and has at most kMaxNodes operands and operators, so a
  /// hostile tree file cannot exhaust the stack.
  static constexpr int kMaxDepth = 64;
  static constexpr int kMaxNodes = 1000;
  struct Nested {
    explicit Nested(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxDepth) parser.fail("nested deeper than 64 levels");
    }
    ~Nested() { --parser.depth_; }
    Parser& parser;
  };
  std::unique_ptr<Expr> node() {
    if (++nodes_ > kMaxNodes) fail("more than 1000 operands and operators");
    return std::make_unique<Expr>();
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("script '" + code_ + "': " + what + " at column " +
                                std::to_string(at_ + 1));
  }
  void skipSpace() {
    while (at_ < code_.size() && std::isspace(static_cast<unsigned char>(code_[at_]))) ++at_;
  }
  /// Consumes `token` if it comes next (an operator `=` is not the start of `==`).
  bool accept(const std::string& token) {
    skipSpace();
    if (code_.compare(at_, token.size(), token) != 0) return false;
    const char next = at_ + token.size() < code_.size() ? code_[at_ + token.size()] : '\0';
    if ((token == "=" || token == "<" || token == ">" || token == "!") && next == '=') return false;
    at_ += token.size();
    return true;
  }
  std::unique_ptr<Expr> binary(Op op, std::unique_ptr<Expr> l, std::unique_ptr<Expr> r) {
    auto e = node();
    e->op = op;
    e->left = std::move(l);
    e->right = std::move(r);
    return e;
  }
  bool nameAt(std::size_t i) const {
    return i < code_.size() &&
           (std::isalpha(static_cast<unsigned char>(code_[i])) || code_[i] == '_');
  }

  std::unique_ptr<Expr> statement() {
    const Nested nested(*this);
    skipSpace();
    const std::size_t start = at_;
    if (nameAt(at_)) {
      std::string name = readName();
      const bool create = accept(":=");
      if (create || accept("=")) {
        auto e = node();
        e->op = create ? Op::kCreate : Op::kAssign;
        e->name = name;
        e->key = keyOf(name);
        e->right = statement();
        return e;
      }
      at_ = start;  // not an assignment: read the name again as a variable
    }
    return orExpr();
  }
  std::unique_ptr<Expr> orExpr() {
    auto e = andExpr();
    while (accept("||")) e = binary(Op::kOr, std::move(e), andExpr());
    return e;
  }
  std::unique_ptr<Expr> andExpr() {
    auto e = comparison();
    while (accept("&&")) e = binary(Op::kAnd, std::move(e), comparison());
    return e;
  }
  std::unique_ptr<Expr> comparison() {
    auto e = sum();
    static const std::pair<const char*, Op> kOps[] = {
        {"==", Op::kEqual},        {"!=", Op::kNotEqual}, {"<=", Op::kLessEqual},
        {">=", Op::kGreaterEqual}, {"<", Op::kLess},      {">", Op::kGreater}};
    for (const auto& [token, op] : kOps) {
      if (accept(token)) return binary(op, std::move(e), sum());
    }
    return e;
  }
  std::unique_ptr<Expr> sum() {
    auto e = product();
    while (true) {
      if (accept("+")) {
        e = binary(Op::kAdd, std::move(e), product());
      } else if (accept("-")) {
        e = binary(Op::kSubtract, std::move(e), product());
      } else {
        return e;
      }
    }
  }
  std::unique_ptr<Expr> product() {
    auto e = unary();
    while (true) {
      if (accept("*")) {
        e = binary(Op::kMultiply, std::move(e), unary());
      } else if (accept("/")) {
        e = binary(Op::kDivide, std::move(e), unary());
      } else {
        return e;
      }
    }
  }
  std::unique_ptr<Expr> unary() {
    const Nested nested(*this);
    if (accept("!")) return binary(Op::kNot, unary(), nullptr);
    if (accept("-")) return binary(Op::kNegate, unary(), nullptr);
    return primary();
  }
  std::unique_ptr<Expr> primary() {
    skipSpace();
    auto e = node();
    if (accept("(")) {
      e = orExpr();
      if (!accept(")")) fail("expected ')'");
      return e;
    }
    if (at_ < code_.size() && code_[at_] == '\'') {
      const std::size_t end = code_.find('\'', at_ + 1);
      if (end == std::string::npos) fail("a string without its closing quote");
      e->literal = code_.substr(at_ + 1, end - at_ - 1);
      at_ = end + 1;
      return e;
    }
    if (at_ < code_.size() &&
        (std::isdigit(static_cast<unsigned char>(code_[at_])) || code_[at_] == '.')) {
      const char* begin = code_.c_str() + at_;
      char* end = nullptr;
      const double value = std::strtod(begin, &end);
      if (end == begin || nameAt(at_ + static_cast<std::size_t>(end - begin))) {
        fail("a malformed number");
      }
      if (!std::isfinite(value)) fail("a number out of range");
      at_ += static_cast<std::size_t>(end - begin);
      e->literal = value;
      return e;
    }
    if (!nameAt(at_)) fail(at_ == code_.size() ? "expected a value" : "unexpected character");
    const std::string name = readName();
    if (name == "true" || name == "false") {
      e->literal = name == "true";
    } else {
      e->op = Op::kVariable;
      e->name = name;
      e->key = keyOf(name);
    }
    return e;
  }
  std::string readName() {
    const std::size_t start = at_;
    while (at_ < code_.size() &&
           (std::isalnum(static_cast<unsigned char>(code_[at_])) || code_[at_] == '_')) {
      ++at_;
    }
    return code_.substr(start, at_ - start);
  }
  std::string keyOf(const std::string& name) const {
    if (name == "true" || name == "false") fail("'" + name + "' cannot be assigned");
    try {
      return key_of_(name);
    } catch (const std::invalid_argument& error) {
      fail(std::string("variable '") + name + "': " + error.what());
    }
  }

  const std::string& code_;
  const Script::KeyOf& key_of_;
  std::size_t at_ = 0;
  int depth_ = 0;
  int nodes_ = 0;
};

template <class Int>
void writeInteger(Blackboard::Entry<Int>& entry, const std::string& name, double v) {
  if (v != std::floor(v) || v < static_cast<double>(std::numeric_limits<Int>::min()) ||
      v > static_cast<double>(std::numeric_limits<Int>::max())) {
    throw ScriptError("'" + name + "' holds " + entry.type_name + ", which cannot take " +
                      show(ScriptValue(v)));
  }
  entry.set(static_cast<Int>(v));
}

bool truth(const ScriptValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b;
  if (const double* d = std::get_if<double>(&v)) return *d != 0;
  throw ScriptError("a string (" + show(v) + ") is neither true nor false");
}

double number(const ScriptValue& v) {
  if (const double* d = std::get_if<double>(&v)) return *d;
  throw ScriptError("arithmetic needs numbers, got " + show(v));
}

ScriptValue evaluate(Blackboard& board, const Expr& e);

ScriptValue compare(Op op, const ScriptValue& a, const ScriptValue& b) {
  if (a.index() != b.index()) {
    throw ScriptError("cannot compare " + show(a) + " with " + show(b));
  }
  if (op == Op::kEqual) return a == b;
  if (op == Op::kNotEqual) return a != b;
  if (std::holds_alternative<bool>(a)) throw ScriptError("booleans are not ordered");
  switch (op) {
    case Op::kLess:
      return a < b;
    case Op::kLessEqual:
      return a <= b;
    case Op::kGreater:
      return a > b;
    default:
      return a >= b;
  }
}

ScriptValue evaluate(Blackboard& board, const Expr& e) {
  switch (e.op) {
    case Op::kLiteral:
      return e.literal;
    case Op::kVariable:
      return readEntry(board, e.key, e.name);
    case Op::kAssign:
    case Op::kCreate: {
      ScriptValue value = evaluate(board, *e.right);
      writeEntry(board, e.key, e.name, value, e.op == Op::kCreate);
      return value;
    }
    case Op::kNot:
      return !truth(evaluate(board, *e.left));
    case Op::kNegate:
      return -number(evaluate(board, *e.left));
    case Op::kAnd:  // short-circuit, as in C++
      return truth(evaluate(board, *e.left)) && truth(evaluate(board, *e.right));
    case Op::kOr:
      return truth(evaluate(board, *e.left)) || truth(evaluate(board, *e.right));
    default:
      break;
  }
  const ScriptValue a = evaluate(board, *e.left);
  const ScriptValue b = evaluate(board, *e.right);
  double result = 0;
  switch (e.op) {
    case Op::kAdd:
      result = number(a) + number(b);
      break;
    case Op::kSubtract:
      result = number(a) - number(b);
      break;
    case Op::kMultiply:
      result = number(a) * number(b);
      break;
    case Op::kDivide:
      if (number(b) == 0) throw ScriptError("division by zero");
      result = number(a) / number(b);
      break;
    default:
      return compare(e.op, a, b);
  }
  if (!std::isfinite(result))
    throw ScriptError("a result out of range (" + show(a) + ", " + show(b) + ")");
  return result;
}

}  // namespace

std::string show(const ScriptValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const std::string* s = std::get_if<std::string>(&value)) return "'" + *s + "'";
  std::ostringstream out;
  out << std::get<double>(value);
  return out.str();
}

ScriptValue readEntry(const Blackboard& board, const std::string& key, const std::string& name) {
  const Blackboard::EntryBase* entry = board.find(key);
  if (!entry || entry->writes == 0) throw ScriptError("'" + name + "' was never written");
  if (const auto* d = dynamic_cast<const Blackboard::Entry<double>*>(entry)) return d->value;
  if (const auto* i = dynamic_cast<const Blackboard::Entry<int>*>(entry)) return double(i->value);
  if (const auto* l = dynamic_cast<const Blackboard::Entry<long>*>(entry)) return double(l->value);
  if (const auto* b = dynamic_cast<const Blackboard::Entry<bool>*>(entry)) return b->value;
  if (const auto* s = dynamic_cast<const Blackboard::Entry<std::string>*>(entry)) return s->value;
  throw ScriptError("'" + name + "' holds " + entry->type_name + ", which scripts cannot read");
}

void writeEntry(Blackboard& board, const std::string& key, const std::string& name,
                const ScriptValue& value, bool create) {
  Blackboard::EntryBase* entry = board.find(key);
  if (!entry) {
    if (!create)
      throw ScriptError("'" + name + "' does not exist (create it with " + name + " := ...)");
    std::visit([&](const auto& v) { board.set(key, v); }, value);
    return;
  }
  const auto mismatch = [&] {
    return ScriptError("'" + name + "' holds " + entry->type_name + ", not " + kindOf(value));
  };
  const double* number = std::get_if<double>(&value);
  if (auto* d = dynamic_cast<Blackboard::Entry<double>*>(entry)) {
    if (!number) throw mismatch();
    d->set(*number);
  } else if (auto* i = dynamic_cast<Blackboard::Entry<int>*>(entry)) {
    if (!number) throw mismatch();
    writeInteger(*i, name, *number);
  } else if (auto* l = dynamic_cast<Blackboard::Entry<long>*>(entry)) {
    if (!number) throw mismatch();
    writeInteger(*l, name, *number);
  } else if (auto* b = dynamic_cast<Blackboard::Entry<bool>*>(entry)) {
    if (!std::holds_alternative<bool>(value)) throw mismatch();
    b->set(std::get<bool>(value));
  } else if (auto* s = dynamic_cast<Blackboard::Entry<std::string>*>(entry)) {
    if (!std::holds_alternative<std::string>(value)) throw mismatch();
    s->set(std::get<std::string>(value));
  } else {
    throw ScriptError("'" + name + "' holds " + entry->type_name + ", which scripts cannot write");
  }
}

Script::Script(const std::string& code, const KeyOf& key_of)
    : code_(code), statements_(Parser(code_, key_of).statements()) {}
Script::~Script() = default;
Script::Script(Script&&) noexcept = default;
Script& Script::operator=(Script&&) noexcept = default;

ScriptValue Script::evaluate(Blackboard& board) const {
  ScriptValue last;
  for (const auto& statement : statements_) last = bt::evaluate(board, *statement);
  return last;
}

bool Script::isTrue(Blackboard& board) const { return truth(evaluate(board)); }

}  // namespace roomba_rrt::bt
