// TryCatch (BehaviorTree.CPP): a Sequence whose failure runs a clean-up child.
#pragma once

#include <cstddef>

#include "roomba_rrt/bt/control_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Two or more children: all but the last are the try block, run as a Sequence; the last is the
/// catch block.
///
/// When a try child returns
/// - SUCCESS (or SKIPPED): the next one is ticked in the same tick; after the last, TryCatch
///   returns SUCCESS (SKIPPED if every try child was skipped).
/// - FAILURE: the try block is halted and the catch child ticked in the same tick, and on the
///   following ticks until it finishes; then TryCatch returns FAILURE (whatever the catch
///   returned).
/// - RUNNING: returns RUNNING and ticks the same child next time.
///
/// Halted in the try block with `catch_on_halt`, it halts the try block and ticks the catch
/// child once (halting it if it is still running) before it stops.
class TryCatchNode final : public ControlNode {
 public:
  static PortList providedPorts() {
    return {inputPort<bool>("catch_on_halt", "run the catch child when halted", "false")};
  }
  TryCatchNode(std::string name, bool catch_on_halt)
      : ControlNode(std::move(name)), catch_on_halt_(catch_on_halt) {}

  std::string childCountProblem(std::size_t children) const override;

 private:
  void onEnter() override {
    current_ = 0;
    executed_ = false;
    catching_ = false;
  }
  Status onTick() override;
  void onHalt() override;
  Status tickCatch();

  bool catch_on_halt_;
  std::size_t current_ = 0;  ///< the try child ticked next
  bool executed_ = false;    ///< a try child was not skipped in this run
  bool catching_ = false;    ///< the catch child is running
};

}  // namespace roomba_rrt::bt
