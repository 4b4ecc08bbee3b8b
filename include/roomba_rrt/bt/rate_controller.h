// RateController (Nav2, BehaviorTree.CPP): tick the child at a rate, e.g. replan at 1 Hz.
#pragma once

#include <cstdint>

#include "roomba_rrt/bt/blackboard.h"
#include "roomba_rrt/bt/decorator_node.h"
#include "roomba_rrt/bt/ports.h"

namespace roomba_rrt::bt {

/// Starts its child at most every `period` ticks, period = max(1, round(tick rate / hz)). Time
/// is the tree's tick count (Blackboard::tick()), no clock. A run starts when RateController is
/// ticked after a tick in which it was not (first tick, after a halt, after its parent went
/// elsewhere) or after a FAILURE: the child is started at once.
///
/// When the child returns
/// - SUCCESS: RateController returns SUCCESS. On the following ticks of the same run it returns
///   RUNNING without ticking the child until `period` ticks have passed since the child was last
///   started, then starts it again (Nav2: replan at a rate, the result held in between).
/// - FAILURE: RateController returns FAILURE; its next tick starts a new run.
/// - RUNNING: RateController returns RUNNING and ticks the child on the next tick.
/// - SKIPPED: returns SKIPPED (the child did not run, so neither does it).
class RateController final : public DecoratorNode {
 public:
  /// `hz` (double, default 1): how often the child is started, in [1e-6, 1000].
  static PortList providedPorts() {
    return {inputPort<double>("hz", "how often the child is started (Hz)", "1.0").range(1e-6, 1e3)};
  }
  /// `hz` and `tick_rate` > 0 and finite (util::InvalidInput naming it otherwise); `clock` (the
  /// tree's blackboard) must outlive the node.
  RateController(std::string name, double hz, double tick_rate, const Blackboard& clock);

  long period() const { return period_; }

 private:
  Status onTick() override;
  void onHalt() override {
    child_->halt();
    last_tick_ = 0;
  }

  const Blackboard& clock_;
  std::uint64_t period_;
  std::uint64_t last_tick_ = 0;   ///< the tick this node was last ticked in (0: none)
  std::uint64_t start_tick_ = 0;  ///< the tick the child was last started in
};

}  // namespace roomba_rrt::bt
