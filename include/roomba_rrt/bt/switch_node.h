// Switch2 ... Switch6 (BehaviorTree.CPP): the child whose case matches a variable runs.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// N cases and N + 1 children: child i runs when `variable` equals `case_i` (the first match),
/// the last child when none does (or `variable` was never written). Values are equal when their
/// texts are, or when both are numbers of the same value ("1" and "1.0").
///
/// Reactive: the cases are compared on every tick; when the match moves, the child that was
/// running is halted. The chosen child's SUCCESS, FAILURE and RUNNING are returned.
class SwitchNode final : public ControlNode {
 public:
  /// `variable` and `case_1` ... `case_<cases>` (strings, literals or keys, required).
  static PortList portsFor(std::size_t cases);
  SwitchNode(std::string name, InputPort<std::string> variable,
             std::vector<InputPort<std::string>> cases);

  std::size_t requiredChildren() const override { return cases_.size() + 1; }
  /// The text equality of the cases, numbers compared by value.
  static bool matches(const std::string& variable, const std::string& value);

 private:
  void onEnter() override { running_ = kNone; }
  Status onTick() override;

  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  InputPort<std::string> variable_;
  std::vector<InputPort<std::string>> cases_;
  std::size_t running_ = kNone;  ///< the child left running last tick
};

}  // namespace roomba_rrt::bt
