// Timeout: give its child a fixed number of ticks to finish.
#pragma once

#include <limits>

#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Lets the child run for at most `ticks` ticks (time is counted in ticks, so a tree is
/// deterministic and needs no clock; at 60 Hz, 60 ticks are one second).
///
/// When the child returns
/// - SUCCESS: Timeout returns SUCCESS.
/// - FAILURE: Timeout returns FAILURE.
/// - RUNNING: Timeout returns RUNNING, unless this was the child's `ticks`-th tick in this run:
///   then the child is halted and Timeout returns FAILURE.
class TimeoutNode final : public DecoratorNode {
 public:
  /// `ticks` (long, required): ticks the child may run, >= 1.
  static PortList providedPorts() {
    return {inputPort<long>("ticks", "ticks the child may run")
                .range(1, static_cast<double>(std::numeric_limits<long>::max()))};
  }
  /// `ticks` ≥ 1 (util::InvalidInput naming it otherwise).
  TimeoutNode(std::string name, long ticks);

 private:
  void onEnter() override { elapsed_ = 0; }
  Status onTick() override;

  long ticks_;
  long elapsed_ = 0;  ///< child ticks in this run
};

}  // namespace roomba_rrt::bt
