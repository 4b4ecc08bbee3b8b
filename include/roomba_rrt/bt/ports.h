// Ports: what a node reads and writes, declared on the node class (providedPorts(), as in
// BehaviorTree.CPP) and bound by the tree file to literals or blackboard keys.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "roomba_rrt/bt/blackboard.h"

namespace roomba_rrt::bt {

/// How a literal attribute becomes a value of type T. Specialize it for an application type
/// that may be written as a literal (the primary template: only blackboard keys, no literal).
/// parse() returns "" and sets `out`, or returns what is wrong ("must be a number, got 'x'").
template <class T, class Enable = void>
struct LiteralParser {
  static constexpr bool kParsable = false;
  static std::string parse(const std::string&, T&) { return "takes a blackboard key like {key}"; }
};

template <>
struct LiteralParser<std::string> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, std::string& out) {
    out = text;
    return "";
  }
};

template <>
struct LiteralParser<bool> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, bool& out) {
    if (text == "true" || text == "1") {
      out = true;
    } else if (text == "false" || text == "0") {
      out = false;
    } else {
      return "must be true or false, got '" + text + "'";
    }
    return "";
  }
};

/// Integers: the whole text in base 10, within the type's range (no wrap-around, no silent
/// clamping: "4294967295" is out of range for int, not "forever").
template <class T>
struct LiteralParser<T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>>> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, T& out) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    if (text.empty() || end != begin + text.size() ||
        std::isspace(static_cast<unsigned char>(text.front()))) {
      return "must be an integer, got '" + text + "'";
    }
    if (errno == ERANGE || value < static_cast<long long>(std::numeric_limits<T>::min()) ||
        value > static_cast<long long>(std::numeric_limits<T>::max())) {
      return "must be an integer in [" + std::to_string(std::numeric_limits<T>::min()) + ", " +
             std::to_string(std::numeric_limits<T>::max()) + "], got " + text;
    }
    out = static_cast<T>(value);
    return "";
  }
};

/// Floating point: the whole text, finite.
template <>
struct LiteralParser<double> {
  static constexpr bool kParsable = true;
  static std::string parse(const std::string& text, double& out) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() ||
        std::isspace(static_cast<unsigned char>(text.front()))) {
      return "must be a number, got '" + text + "'";
    }
    if (!std::isfinite(value)) return "must be finite, got " + text;
    out = value;
    return "";
  }
};

/// kInOut: a key the node both reads and writes (BehaviorTree.CPP's BidirectionalPort, Groot2's
/// inout_port); like an output it needs a key, and it counts as writing it.
enum class PortDirection : std::uint8_t { kInput, kOutput, kInOut };

/// One port of a node type: name, direction, type, default (none: the port is required),
/// description, and for numbers the accepted range of a literal.
struct PortInfo {
  std::string name;
  PortDirection direction = PortDirection::kInput;
  std::string type_name;
  std::optional<std::string> default_value;
  std::string description;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  /// A plain attribute of a node registered without ports (TreeFactory::registerNode with
  /// attribute names): passed to the builder as text, never a blackboard key.
  bool raw = false;

  /// Declares `key` with this port's type on `board` (std::invalid_argument on another type).
  void (*declare)(Blackboard& board, const std::string& key) = nullptr;
  /// "" when `text` is a valid literal for this port (type and range), else what is wrong.
  std::string (*check)(const PortInfo& port, const std::string& text) = nullptr;

  bool required() const { return !default_value.has_value(); }
  /// Literals outside [lo, hi] are refused (numbers only).
  PortInfo& range(double lo, double hi) {
    min = lo;
    max = hi;
    return *this;
  }
};

using PortList = std::vector<PortInfo>;

namespace detail {

template <class T>
void declareKey(Blackboard& board, const std::string& key) {
  board.declare<T>(key);
}

inline std::string formatNumber(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return std::to_string(v);
}

template <class T>
std::string checkLiteral(const PortInfo& port, const std::string& text) {
  T value{};
  std::string error = LiteralParser<T>::parse(text, value);
  if (!error.empty()) return error;
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    const double v = static_cast<double>(value);
    if (v < port.min || v > port.max) {
      return "must be in [" + formatNumber(port.min) + ", " + formatNumber(port.max) + "], got " +
             text;
    }
  }
  return "";
}

template <class T>
PortInfo makePort(PortDirection direction, std::string name, std::string description,
                  std::optional<std::string> default_value) {
  PortInfo port;
  port.name = std::move(name);
  port.direction = direction;
  port.type_name = TypeName<T>::get();
  port.default_value = std::move(default_value);
  port.description = std::move(description);
  port.declare = &declareKey<T>;
  port.check = &checkLiteral<T>;
  return port;
}

}  // namespace detail

/// An input port: a literal in the tree file, or a blackboard key `{key}` the node reads.
///
/// The order of the arguments differs from BehaviorTree.CPP's: BT.CPP writes
/// `InputPort<T>(name, default, description)`, we write `inputPort<T>(name, description,
/// default)`, because here every port has a description and most have no default (a port
/// without one is required). Both orders take strings, so a port ported from BT.CPP must have
/// its last two arguments swapped; TreeNodesModel output (Groot2) is the same either way.
template <class T>
PortInfo inputPort(std::string name, std::string description,
                   std::optional<std::string> default_value = std::nullopt) {
  return detail::makePort<T>(PortDirection::kInput, std::move(name), std::move(description),
                             std::move(default_value));
}

/// An output port: always a blackboard key `{key}` the node writes. Arguments in inputPort()'s
/// order (name, description, default).
template <class T>
PortInfo outputPort(std::string name, std::string description,
                    std::optional<std::string> default_value = std::nullopt) {
  return detail::makePort<T>(PortDirection::kOutput, std::move(name), std::move(description),
                             std::move(default_value));
}

/// A port the node reads and writes (BehaviorTree.CPP's BidirectionalPort): always a blackboard
/// key `{key}`, bound with NodeSpec::output() (an OutputPort reads too). Arguments in
/// inputPort()'s order.
template <class T>
PortInfo inoutPort(std::string name, std::string description,
                   std::optional<std::string> default_value = std::nullopt) {
  return detail::makePort<T>(PortDirection::kInOut, std::move(name), std::move(description),
                             std::move(default_value));
}

/// `text` is a blackboard reference `{key}`: sets `key` and returns true.
inline bool parseBlackboardKey(const std::string& text, std::string& key) {
  if (text.size() < 3 || text.front() != '{' || text.back() != '}') return false;
  key = text.substr(1, text.size() - 2);
  return true;
}

/// What a node reads through an input port: the literal, or the blackboard entry (which may
/// not have been written yet: get() is then nullptr). Copyable; reading is one branch.
template <class T>
class InputPort {
 public:
  InputPort() = default;
  static InputPort literal(T value) {
    InputPort port;
    port.literal_ = std::move(value);
    return port;
  }
  static InputPort key(const Blackboard::Entry<T>& entry) {
    InputPort port;
    port.entry_ = &entry;
    return port;
  }

  /// The value, or nullptr when it comes from a key nothing has written yet.
  const T* get() const { return entry_ ? entry_->get() : &literal_; }
  /// How often the value was written (a literal: 1), to notice a new value.
  std::uint64_t writes() const { return entry_ ? entry_->writes : 1; }

 private:
  T literal_{};
  const Blackboard::Entry<T>* entry_ = nullptr;
};

/// What a node writes through an output port (a blackboard entry).
template <class T>
class OutputPort {
 public:
  OutputPort() = default;
  explicit OutputPort(Blackboard::Entry<T>& entry) : entry_(&entry) {}

  void set(const T& value) { entry_->set(value); }
  /// The stored value, to fill in place (no copy, no allocation when its capacity suffices);
  /// call commit() afterwards so readers see a new write.
  T& value() { return entry_->value; }
  void commit() { ++entry_->writes; }
  void clear() { entry_->clear(); }
  const T* get() const { return entry_->get(); }

 private:
  Blackboard::Entry<T>* entry_ = nullptr;
};

}  // namespace roomba_rrt::bt
